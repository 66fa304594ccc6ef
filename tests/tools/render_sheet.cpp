// Test and example tooling: a contact sheet of meshes a person can look at -- each mesh
// rasterised (lib/reflectance) from one shared camera, Lambert-shaded by a light at the
// camera plus a little ambient, labelled, tiled COLS per row -- with OpenCV.
//
//   render_sheet OUT.png COLS TILE VIEW LABEL=MESH...
//   VIEW: side (looking along -z, x up: the sagittal view of softobj's tongue),
//         top (looking along -x), or iso (three-quarter)

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "mesh_picture.hpp"
#include "reflectance/rasterizer.hpp"

using fest::reflectance::TriangleMesh;

int main(int argc, char** argv) {
  return fest::run_tool("render_sheet", [&] {
    if (argc < 6) throw fest::usage_error("usage: render_sheet OUT.png COLS TILE VIEW LABEL=MESH...");
    const int cols = std::atoi(argv[2]), tile = std::atoi(argv[3]);
    const std::string view = argv[4];
    if (cols < 1 || tile < 32 || tile > 4096) throw fest::usage_error("COLS >= 1, TILE in 32..4096");
    std::vector<TriangleMesh> meshes;
    std::vector<std::string> labels;
    for (int i = 5; i < argc; ++i) {
      const std::string arg = argv[i];
      const auto eq = arg.find('=');
      labels.push_back(eq == std::string::npos ? "" : arg.substr(0, eq));
      TriangleMesh t = fest::test_tools::triangles_of(
          fest::test_tools::read_mesh_file(eq == std::string::npos ? arg : arg.substr(eq + 1)));
      fest::reflectance::compute_vertex_normals(t);
      meshes.push_back(std::move(t));
    }
    // One camera for all tiles: the union's bounding sphere fills the tile.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& m : meshes)
      for (const auto& v : m.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    const double radius = 0.5 * (hi - lo).norm();
    Eigen::Vector3d dir(0, 0, 1), up(1, 0, 0);
    if (view == "top") dir = {1, 0, 0}, up = {0, 1, 0};
    if (view == "iso") dir = Eigen::Vector3d(0.5, -0.6, 0.8).normalized(), up = {1, 0, 0};
    fest::reflectance::PinholeCamera cam;
    const Eigen::Vector3d eye = centre + 4 * radius * dir;
    cam.R = fest::reflectance::look_at_rotation(eye, centre, up);
    cam.t = -cam.R * eye;
    cam.width = cam.height = tile;
    cam.fx = cam.fy = 0.5 * tile / std::tan(std::asin(1.0 / 4)) * 0.95;
    cam.cx = cam.cy = 0.5 * tile;
    const int rows = (static_cast<int>(meshes.size()) + cols - 1) / cols;
    cv::Mat sheet(rows * tile, cols * tile, CV_8UC3, cv::Scalar(255, 255, 255));
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      const auto frags = fest::reflectance::rasterize(meshes[i], cam);
      cv::Mat img = sheet(cv::Rect(static_cast<int>(i % cols) * tile, static_cast<int>(i / cols) * tile, tile, tile));
      fest::test_tools::paint_fragments(img, meshes[i], frags, [&](std::size_t, const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
        const double s = 0.15 + 0.85 * std::abs(n.dot((eye - p).normalized()));
        return cv::Vec3b(static_cast<uchar>(120 * s), static_cast<uchar>(140 * s),
                         static_cast<uchar>(235 * s));  // BGR: a tongue pink
      });
      cv::putText(img, labels[i], {8, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
      cv::rectangle(img, {0, 0}, {tile - 1, tile - 1}, cv::Scalar(200, 200, 200));
    }
    fest::test_tools::write_png(argv[1], sheet);
    return 0;
  });
}

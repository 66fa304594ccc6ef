// Test and example tooling: a Lambert-shaded picture of one or more meshes, drawn with
// lib/reflectance's rasteriser, so a person can look at what decimate and ffd made.
// Several meshes share one camera (fitted to all of them) and are drawn side by side
// when --side is given, else overlaid in one scene; --wire darkens pixels near triangle
// edges (shows the triangulation).
//
//   render_mesh OUT.png MESH... [--size W] [--view x,y,z] [--up x,y,z] [--side] [--wire]

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "mesh_picture.hpp"
#include "reflectance/rasterizer.hpp"

namespace {

using fest::reflectance::TriangleMesh;

Eigen::Vector3d parse3(const std::string& s) {
  Eigen::Vector3d v;
  if (std::sscanf(s.c_str(), "%lf,%lf,%lf", &v[0], &v[1], &v[2]) != 3) throw fest::usage_error("'{}' is not x,y,z", s);
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  return fest::run_tool("render_mesh", [&] {
    if (argc < 3) throw fest::usage_error("usage: render_mesh OUT.png MESH... [--size W] [--view x,y,z] [--up x,y,z] [--side] [--wire]");
    const std::string out = argv[1];
    std::vector<std::string> paths;
    int size = 800;
    Eigen::Vector3d view(0.3, 0.2, 1.0), up(0, 1, 0);
    bool side = false, wire = false;
    for (int i = 2; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--size" && i + 1 < argc) size = std::atoi(argv[++i]);
      else if (a == "--view" && i + 1 < argc) view = parse3(argv[++i]);
      else if (a == "--up" && i + 1 < argc) up = parse3(argv[++i]);
      else if (a == "--side") side = true;
      else if (a == "--wire") wire = true;
      else paths.push_back(a);
    }
    if (size < 64 || size > 8192) throw fest::usage_error("--size {} is outside 64..8192", size);
    std::vector<fest::Mesh> meshes;
    for (const auto& p : paths) meshes.push_back(fest::test_tools::read_mesh_file(p));
    // One scene: side by side along the camera's right vector, or overlaid.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& m : meshes)
      for (const auto v : m.vertices()) {
        const Eigen::Vector3d p(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    const Eigen::Vector3d dir = view.normalized();
    const Eigen::Vector3d right = up.cross(dir).normalized();
    const double extent = (hi - lo).norm();
    TriangleMesh scene;
    std::vector<int> owner;
    for (std::size_t k = 0; k < meshes.size(); ++k) {
      const double offset = side ? (static_cast<double>(k) - 0.5 * (meshes.size() - 1)) * extent : 0.0;
      TriangleMesh t = fest::test_tools::triangles_of(meshes[k], offset * right);
      const auto base = static_cast<std::uint32_t>(scene.vertices.size());
      scene.vertices.insert(scene.vertices.end(), t.vertices.begin(), t.vertices.end());
      for (auto tri : t.triangles) {
        for (auto& c : tri) c += base;
        scene.triangles.push_back(tri);
        owner.push_back(static_cast<int>(k));
      }
    }
    fest::reflectance::compute_vertex_normals(scene);
    Eigen::Vector3d centre;
    double radius = 0;
    fest::reflectance::bounding_sphere(scene, centre, radius);
    const double aspect = side ? static_cast<double>(meshes.size()) : 1.0;
    fest::reflectance::PinholeCamera cam;
    cam.width = static_cast<int>(size * std::min(aspect, 3.0));
    cam.height = size;
    const double fov = 0.1;  // half-angle tangent: a long lens, so side-by-side meshes are seen alike
    cam.fx = cam.fy = 0.5 * size / fov;
    cam.cx = 0.5 * cam.width;
    cam.cy = 0.5 * cam.height;
    // Far enough that the sphere fits across and one mesh's extent fits vertically.
    const double wide = std::min(aspect, 3.0);
    const double distance = side ? std::max(radius * 1.1 / (fov * wide), 0.6 * extent / fov) : radius * 1.1 / fov;
    const Eigen::Vector3d eye = centre + dir * distance;
    cam.R = fest::reflectance::look_at_rotation(eye, centre, up);
    cam.t = -cam.R * eye;
    fest::reflectance::RasterOptions ro;
    ro.threads = 2;
    const auto frag = fest::reflectance::rasterize(scene, cam, ro);
    cv::Mat img(cam.height, cam.width, CV_8UC3, cv::Scalar(255, 255, 255));
    const Eigen::Vector3d light = (dir + 0.5 * up.normalized() + 0.3 * right).normalized();
    const cv::Vec3b colours[4] = {{200, 170, 120}, {120, 180, 220}, {140, 210, 140}, {200, 140, 200}};
    fest::test_tools::paint_fragments(img, scene, frag, [&](std::size_t i, const Eigen::Vector3d& p, Eigen::Vector3d n) {
      if (n.dot(cam.centre() - p) < 0) n = -n;
      double shade = 0.25 + 0.75 * std::max(0.0, n.dot(light));
      if (wire) {
        const double b1 = frag.b1[i], b2 = frag.b2[i], b0 = 1 - b1 - b2;
        if (std::min({b0, b1, b2}) < 0.03) shade *= 0.45;
      }
      const cv::Vec3b c = colours[owner[static_cast<std::size_t>(frag.triangle[i])] % 4];
      return cv::Vec3b(static_cast<unsigned char>(c[0] * shade), static_cast<unsigned char>(c[1] * shade),
                       static_cast<unsigned char>(c[2] * shade));
    });
    fest::test_tools::write_png(out, img);
    return 0;
  });
}

#include "view.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "reflectance/camera.hpp"
#include "reflectance/rasterizer.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::radiosity_tool {
namespace {

Eigen::Vector3d vec(const std::vector<double>& v, const char* what) {
  if (v.size() != 3) throw usage_error("--{} needs three numbers x,y,z", what);
  return {v[0], v[1], v[2]};
}

}  // namespace

cv::Mat render_values(const ViewMesh& mesh, const CameraArgs& args, int threads) {
  if (mesh.positions.empty()) throw bad_input("nothing to render: the mesh has no vertices");
  Eigen::Vector3d lo = mesh.positions.front(), hi = lo;
  for (const auto& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-12});
  const Eigen::Vector3d target = args.target.empty() ? centre : vec(args.target, "target");
  // Default: from in front of the box (z below it) at the distance the Cornell camera has
  // (800 mm for a 556 mm box: 1.44 extents).
  const Eigen::Vector3d eye =
      args.eye.empty() ? Eigen::Vector3d(centre.x(), centre.y(), lo.z() - 1.44 * extent) : vec(args.eye, "eye");
  const Eigen::Vector3d up = args.up.empty() ? Eigen::Vector3d(0, 1, 0) : vec(args.up, "up");
  if ((target - eye).norm() <= 0 || up.cross(target - eye).norm() <= 0)
    throw usage_error("camera: eye, target and up must not be collinear");
  reflectance::PinholeCamera cam;
  cam.width = args.width;
  cam.height = args.height > 0 ? args.height : args.width;
  cam.fy = 0.5 * cam.height / std::tan(0.5 * args.fov * M_PI / 180.0);
  cam.fx = cam.fy;
  cam.cx = 0.5 * (cam.width - 1);
  cam.cy = 0.5 * (cam.height - 1);
  cam.R = reflectance::look_at_rotation(eye, target, up);
  cam.t = -cam.R * eye;
  reflectance::TriangleMesh tm;
  tm.vertices = mesh.positions;
  tm.triangles = mesh.triangles;
  reflectance::compute_vertex_normals(tm);
  reflectance::RasterOptions ro;
  ro.threads = threads;
  const reflectance::Fragments f = reflectance::rasterize(tm, cam, ro);
  cv::Mat out(cam.height, cam.width, CV_32FC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const std::size_t i = f.index(x, y);
      if (f.triangle[i] < 0) continue;
      const auto& t = mesh.triangles[static_cast<std::size_t>(f.triangle[i])];
      const double b1 = f.b1[i], b2 = f.b2[i], b0 = 1 - b1 - b2;
      const Eigen::Vector3d v = b0 * mesh.values[t[0]] + b1 * mesh.values[t[1]] + b2 * mesh.values[t[2]];
      out.at<cv::Vec3f>(y, x) = cv::Vec3f(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    }
  return out;
}

Image to_display(const cv::Mat& values, double scale, double gamma) {
  Image img;
  img.pixels.create(values.rows, values.cols, CV_8UC3);
  img.color_space = ColorSpace::srgb;
  for (int y = 0; y < values.rows; ++y)
    for (int x = 0; x < values.cols; ++x) {
      const cv::Vec3f v = values.at<cv::Vec3f>(y, x);
      cv::Vec3b& o = img.pixels.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c)
        o[c] = static_cast<std::uint8_t>(std::lround(255.0 * std::pow(std::clamp(scale * v[c], 0.0, 1.0), gamma)));
    }
  return img;
}

}  // namespace fest::radiosity_tool

#include "markers/overlay.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

#include "reflectance/rasterizer.hpp"

namespace fest::markers {

namespace {

reflectance::PinholeCamera pinhole(const CameraModel& c, const Pose& pose) {
  reflectance::PinholeCamera p;
  p.fx = c.K(0, 0);
  p.fy = c.K(1, 1);
  p.cx = c.K(0, 2);
  p.cy = c.K(1, 2);
  p.width = c.width;
  p.height = c.height;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) p.R(r, k) = pose.R(r, k);
    p.t[r] = pose.t[r];
  }
  return p;
}

// The ideal (undistorted) image that covers every ray the real image sees: its camera
// (principal point shifted by the margin) and, for every pixel of the distorted image,
// the index of the ideal pixel that shows the same ray (nearest pixel centre). A barrel
// lens sees rays beyond the ideal image of the same size, hence the margin.
struct IdealView {
  int width = 0, height = 0;
  double shift_x = 0, shift_y = 0;
  std::vector<int> lookup;
};

IdealView ideal_view(const CameraModel& c) {
  IdealView v;
  v.lookup.resize(static_cast<std::size_t>(c.width) * c.height);
  if (!c.has_distortion()) {
    v.width = c.width;
    v.height = c.height;
    for (std::size_t i = 0; i < v.lookup.size(); ++i) v.lookup[i] = static_cast<int>(i);
    return v;
  }
  std::vector<cv::Point2d> px, ideal;
  px.reserve(v.lookup.size());
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) px.emplace_back(x, y);
  cv::undistortPoints(px, ideal, cv::Mat(c.K), cv::Mat(c.dist), cv::noArray(), cv::Mat(c.K),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
  double x0 = 0, y0 = 0, x1 = c.width - 1, y1 = c.height - 1;
  for (const cv::Point2d& p : ideal) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  // Bounded: a lens model that folds rays far outside is not worth a huge buffer.
  x0 = std::max(x0, -1.0 * c.width), y0 = std::max(y0, -1.0 * c.height);
  x1 = std::min(x1, 2.0 * c.width), y1 = std::min(y1, 2.0 * c.height);
  v.shift_x = -std::floor(x0);
  v.shift_y = -std::floor(y0);
  v.width = static_cast<int>(std::ceil(x1) + v.shift_x) + 1;
  v.height = static_cast<int>(std::ceil(y1) + v.shift_y) + 1;
  for (std::size_t i = 0; i < v.lookup.size(); ++i) {
    const long x = std::lround(ideal[i].x + v.shift_x), y = std::lround(ideal[i].y + v.shift_y);
    v.lookup[i] = x < 0 || y < 0 || x >= v.width || y >= v.height ? -1 : static_cast<int>(y * v.width + x);
  }
  return v;
}

reflectance::PinholeCamera ideal_camera(const CameraModel& c, const Pose& pose, const IdealView& v) {
  reflectance::PinholeCamera p = pinhole(c, pose);
  p.cx += v.shift_x;
  p.cy += v.shift_y;
  p.width = v.width;
  p.height = v.height;
  return p;
}

}  // namespace

std::vector<std::uint8_t> overlay_mask(const reflectance::TriangleMesh& mesh, const CameraModel& camera,
                                       const Pose& pose, int threads) {
  const IdealView view = ideal_view(camera);
  const std::vector<std::uint8_t> ideal =
      reflectance::rasterize_silhouette(mesh, ideal_camera(camera, pose, view), threads);
  const std::vector<int>& lut = view.lookup;
  std::vector<std::uint8_t> out(lut.size(), 0);
  for (std::size_t i = 0; i < lut.size(); ++i) out[i] = lut[i] >= 0 ? ideal[static_cast<std::size_t>(lut[i])] : 0;
  return out;
}

void draw_overlay(cv::Mat& rgb8, const reflectance::TriangleMesh& mesh, const CameraModel& camera,
                  const std::vector<Pose>& poses, const OverlayStyle& style) {
  CV_Assert(rgb8.type() == CV_8UC3 && rgb8.cols == camera.width && rgb8.rows == camera.height);
  if (poses.empty()) return;
  reflectance::TriangleMesh shaded = mesh;
  if (shaded.normals.size() != shaded.vertices.size()) reflectance::compute_vertex_normals(shaded);
  const IdealView view = ideal_view(camera);
  const std::vector<int>& lut = view.lookup;
  for (const Pose& pose : poses) {
    const reflectance::PinholeCamera cam = ideal_camera(camera, pose, view);
    reflectance::RasterOptions ro;
    ro.threads = style.threads;
    const reflectance::Fragments f = reflectance::rasterize(shaded, cam, ro);
    for (int y = 0; y < camera.height; ++y)
      for (int x = 0; x < camera.width; ++x) {
        const int src = lut[static_cast<std::size_t>(y) * camera.width + x];
        if (src < 0 || f.triangle[static_cast<std::size_t>(src)] < 0) continue;
        // Headlight Lambert shading: |n . view direction| in the camera frame.
        const Eigen::Vector3d p = reflectance::fragment_point(shaded, f, static_cast<std::size_t>(src));
        const Eigen::Vector3d n = cam.R * reflectance::fragment_normal(shaded, f, static_cast<std::size_t>(src));
        const Eigen::Vector3d v = -cam.to_camera(p).normalized();
        const double shade = 0.35 + 0.65 * std::abs(n.dot(v));
        cv::Vec3b& px = rgb8.at<cv::Vec3b>(y, x);
        for (int k = 0; k < 3; ++k)
          px[k] = cv::saturate_cast<uchar>((1 - style.opacity) * px[k] + style.opacity * shade * style.colour[k]);
      }
  }
}

reflectance::TriangleMesh marker_cube(double side) {
  const double h = side / 2;
  std::vector<Eigen::Vector3d> corner;
  for (int i = 0; i < 8; ++i) corner.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? side : 0.0);
  // Four vertices per face (outward winding), so that each face shades flat.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  reflectance::TriangleMesh m;
  for (const auto& q : quads) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int k = 0; k < 4; ++k) m.vertices.push_back(corner[static_cast<std::size_t>(q[k])]);
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
  }
  reflectance::compute_vertex_normals(m);
  return m;
}

}  // namespace fest::markers

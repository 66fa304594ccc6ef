#include "capture/calib_synth.hpp"

#include <cmath>

#include <opencv2/calib3d.hpp>

namespace fest::capture {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

PixelRays::PixelRays(const Intrinsics& camera, int samples)
    : samples_(samples), width_(camera.width), height_(camera.height) {
  // Pixel (x, y) covers [x - 0.5, x + 0.5] x [y - 0.5, y + 0.5]; undistort its corners
  // and interpolate inside (distortion is smooth over one pixel).
  std::vector<cv::Point2d> grid;
  grid.reserve(std::size_t((width_ + 1) * (height_ + 1)));
  for (int y = 0; y <= height_; ++y)
    for (int x = 0; x <= width_; ++x) grid.emplace_back(x - 0.5, y - 0.5);
  std::vector<cv::Point2d> undistorted;
  cv::undistortPoints(grid, undistorted, cv::Mat(camera.K), cv::Mat(camera.dist).reshape(1, 1), cv::noArray(),
                      cv::noArray(), cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-14));
  corners_ = cv::Mat(undistorted, true).reshape(2, height_ + 1);
}

cv::Vec3d PixelRays::ray(int x, int y, int sx, int sy) const {
  const double fx = (sx + 0.5) / samples_, fy = (sy + 0.5) / samples_;
  const cv::Vec2d a = corners_.at<cv::Vec2d>(y, x), b = corners_.at<cv::Vec2d>(y, x + 1);
  const cv::Vec2d c = corners_.at<cv::Vec2d>(y + 1, x), d = corners_.at<cv::Vec2d>(y + 1, x + 1);
  const cv::Vec2d p = (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
  return cv::Vec3d(p[0], p[1], 1);
}

cv::Mat render_board(const Intrinsics& camera, const BoardSpec& board, const Pose& pose, int samples) {
  const PixelRays rays(camera, samples);
  const cv::Vec3d n(pose.R(0, 2), pose.R(1, 2), pose.R(2, 2));  // board normal in C
  const double nt = n.dot(pose.t);
  const double s = board.square;
  cv::Mat out(camera.height, camera.width, CV_8U);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      double sum = 0;
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx) {
          const cv::Vec3d d = rays.ray(x, y, sx, sy);
          const double nd = n.dot(d);
          double value = 0.5;
          if (std::abs(nd) > 1e-12 && nt / nd > 0) {
            const cv::Vec3d P = pose.R.t() * (d * (nt / nd) - pose.t);
            const double i = std::floor(P[0] / s), j = std::floor(P[1] / s);
            if (i >= -1 && i <= board.cols - 1 && j >= -1 && j <= board.rows - 1)
              value = (long(i) + long(j)) % 2 == 0 ? 0.1 : 0.9;
            else if (i >= -2 && i <= board.cols && j >= -2 && j <= board.rows)
              value = 0.9;
          }
          sum += value;
        }
      out.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(255 * sum / (samples * samples));
    }
  return out;
}

cv::Vec3d mirror_point(const Sphere& sphere, const cv::Vec3d& light) {
  // Bisection on the great circle through the directions to camera and light: the
  // normal n(t) = normalize(mix) for which the mirrored viewing ray hits the light.
  const cv::Vec3d to_cam = cv::normalize(-sphere.centre), to_light = cv::normalize(light - sphere.centre);
  auto error = [&](double t) {
    const cv::Vec3d nrm = cv::normalize(to_cam * (1 - t) + to_light * t);
    const cv::Vec3d h = sphere.centre + nrm * sphere.radius;
    const cv::Vec3d l = cv::normalize(light - h), c = cv::normalize(-h);
    // Angle of l beyond the mirror of c about n, signed along the circle.
    const cv::Vec3d mirrored = 2 * c.dot(nrm) * nrm - c;
    return (l - mirrored).dot(to_light - to_cam);
  };
  double lo = 0, hi = 1;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    if ((error(lo) < 0) == (error(mid) < 0)) lo = mid; else hi = mid;
  }
  const cv::Vec3d nrm = cv::normalize(to_cam * (1 - lo) + to_light * lo);
  return sphere.centre + nrm * sphere.radius;
}

cv::Mat render_spheres(const Intrinsics& camera, const std::vector<Sphere>& spheres, const cv::Vec3d& light,
                       double lobe_sigma_deg, int samples) {
  const PixelRays rays(camera, samples);
  const double sigma = lobe_sigma_deg * kPi / 180;
  cv::Mat out(camera.height, camera.width, CV_16U);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      double sum = 0;
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx) {
          const cv::Vec3d d = cv::normalize(rays.ray(x, y, sx, sy));
          double nearest = 1e300, value = 0.02;
          for (const Sphere& sp : spheres) {
            const double b = d.dot(sp.centre), disc = b * b - sp.centre.dot(sp.centre) + sp.radius * sp.radius;
            if (disc < 0) continue;
            const double t = b - std::sqrt(disc);
            if (t <= 0 || t >= nearest) continue;
            nearest = t;
            const cv::Vec3d h = d * t, nrm = (h - sp.centre) / sp.radius;
            const cv::Vec3d r = d - 2 * d.dot(nrm) * nrm;
            const double theta = std::acos(std::clamp(r.dot(cv::normalize(light - h)), -1.0, 1.0));
            value = 0.3 + 0.65 * std::exp(-theta * theta / (2 * sigma * sigma));
          }
          sum += value;
        }
      out.at<std::uint16_t>(y, x) = cv::saturate_cast<std::uint16_t>(65535 * sum / (samples * samples));
    }
  return out;
}

}  // namespace fest::capture

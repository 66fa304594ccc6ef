#include "markers/synth.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace fest::markers {

namespace {

constexpr int k_supersample = 4;

// Reflectance 0 (black) .. 1 (white) of the marker at marker-plane point (x, y); -1 off
// the printed area (quiet zone included).
double marker_value(const PlacedMarker& m, double x, double y, const cv::Rect2d& occluder) {
  const double s = m.side;
  if (m.art.bits > 0) {
    const int cells = m.art.bits + 2;
    const double cell = s / cells;
    const double q = m.art.quiet_zone * cell;
    if (std::abs(x) > s / 2 + q || std::abs(y) > s / 2 + q) return -1;
    if (std::abs(x) >= s / 2 || std::abs(y) >= s / 2) return 1;  // quiet zone
    const double cx = (x + s / 2) / cell, cy = (s / 2 - y) / cell;
    if (occluder.contains(cv::Point2d(cx, cy))) return -2;
    const int c = std::min(cells - 1, static_cast<int>(cx)), r = std::min(cells - 1, static_cast<int>(cy));
    if (r == 0 || c == 0 || r == cells - 1 || c == cells - 1) return 0;
    const int n = m.art.bits;
    const int bit = n * n - 1 - ((r - 1) * n + (c - 1));
    return double((m.art.code >> bit) & 1u);
  }
  const double q = s / 8;
  if (std::abs(x) > s / 2 + q || std::abs(y) > s / 2 + q) return -1;
  if (std::abs(x) >= s / 2 || std::abs(y) >= s / 2) return 1;
  // Pattern: 4 x 4 cell layout, the picture fills cells [1, 3) x [1, 3).
  const double cx = (x + s / 2) / s * 4, cy = (s / 2 - y) / s * 4;
  if (occluder.contains(cv::Point2d(cx, cy))) return -2;
  if (cx < 1 || cx >= 3 || cy < 1 || cy >= 3) return 0;
  const cv::Mat& p = m.art.picture;
  const int px = std::min(p.cols - 1, static_cast<int>((cx - 1) / 2 * p.cols));
  const int py = std::min(p.rows - 1, static_cast<int>((cy - 1) / 2 * p.rows));
  return p.at<uchar>(py, px) / 255.0;
}

cv::Mat background(int w, int h, const Degradation& d, Rng& rng) {
  cv::Mat bg(h, w, CV_32F);
  const double mid = 0.5 * (d.black + d.white), amp = 0.25 * (d.white - d.black);
  const double fx1 = rng.uniform(0.005, 0.03), fy1 = rng.uniform(0.005, 0.03), ph = rng.uniform(0, 6.28);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      bg.at<float>(y, x) = float(mid + (d.clutter ? amp * std::sin(fx1 * x + fy1 * y + ph) : 0.0));
  if (d.clutter) {
    // Distractors: dark and light rectangles and bars (non-marker quads and edges).
    const int count = 12;
    for (int i = 0; i < count; ++i) {
      const int rw = int(rng.uniform(4, w / 6.0)), rh = int(rng.uniform(4, h / 6.0));
      const int rx = int(rng.uniform(0, w - rw)), ry = int(rng.uniform(0, h - rh));
      const double level = rng.uniform() < 0.5 ? d.black + rng.uniform(0, 30) : d.white - rng.uniform(0, 30);
      cv::rectangle(bg, cv::Rect(rx, ry, rw, rh), cv::Scalar(level), cv::FILLED);
    }
  }
  return bg;
}

}  // namespace

MarkerArt binary_art(const Dictionary& dict, int id) {
  if (id < 0 || id >= static_cast<int>(dict.codes.size()))
    throw bad_input("marker id {} is not in dictionary {} (0..{})", id, dict.name, dict.codes.size() - 1);
  MarkerArt a;
  a.bits = dict.bits;
  a.code = dict.codes[static_cast<std::size_t>(id)];
  return a;
}

Corners project_corners(const CameraModel& camera, const Pose& pose, double side) {
  const auto obj = square_object_points(side);
  std::vector<cv::Point3d> o(obj.begin(), obj.end());
  std::vector<cv::Point2d> p;
  cv::projectPoints(o, rotation_vector(pose.R), pose.t, cv::Mat(camera.K), cv::Mat(camera.dist), p);
  return {p[0], p[1], p[2], p[3]};
}

cv::Mat render_scene(const CameraModel& camera, const std::vector<PlacedMarker>& markers, const Degradation& d,
                     std::uint64_t seed, const cv::Mat& photo) {
  const int w = camera.width, h = camera.height;
  if (w <= 0 || h <= 0) throw bad_input("camera size {}x{} is not positive", w, h);
  Rng rng(seed);
  cv::Mat img;
  if (photo.empty()) {
    img = background(w, h, d, rng);
  } else {
    if (photo.type() != CV_8UC1 || photo.cols != w || photo.rows != h)
      throw bad_input("background photo is {}x{}, the camera {}x{}", photo.cols, photo.rows, w, h);
    photo.convertTo(img, CV_32F);
  }
  const cv::Matx33d Kinv = camera.K.inv();
  for (const PlacedMarker& m : markers) {
    // Occluder in cell units over the interior (never the border: a broken border is a
    // lost quad, which no decoder can help).
    cv::Rect2d occluder(0, 0, 0, 0);
    const double lo = m.art.bits > 0 ? 1 : 1, span = m.art.bits > 0 ? m.art.bits : 2;
    if (d.occlusion > 0) {
      const double side = span * std::sqrt(std::min(1.0, d.occlusion));
      occluder = cv::Rect2d(lo + rng.uniform(0, span - side), lo + rng.uniform(0, span - side), side, side);
    }
    const double occ_level = rng.uniform(0.2, 0.8);
    // Pixel bounding box of the printed area (quiet zone included), from its corners.
    const double q = m.art.bits > 0 ? m.side * (1 + 2 * m.art.quiet_zone / (m.art.bits + 2)) : m.side * 1.25;
    const Corners outer = project_corners(camera, m.pose, q);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const cv::Point2d& p : outer) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    const int ix0 = std::max(0, int(std::floor(x0)) - 2), iy0 = std::max(0, int(std::floor(y0)) - 2);
    const int ix1 = std::min(w - 1, int(std::ceil(x1)) + 2), iy1 = std::min(h - 1, int(std::ceil(y1)) + 2);
    if (ix0 > ix1 || iy0 > iy1) continue;
    const cv::Vec3d n(m.pose.R(0, 2), m.pose.R(1, 2), m.pose.R(2, 2));
    const double nt = n.dot(m.pose.t);
    const cv::Matx33d Rt = m.pose.R.t();
    // Rays through the pixel corners of the box (undistorted once per corner); the 4 x 4
    // samples inside a pixel interpolate them bilinearly (distortion is smooth at that scale).
    const int gw = ix1 - ix0 + 2, gh = iy1 - iy0 + 2;
    std::vector<cv::Point2d> grid, rays_grid;
    grid.reserve(static_cast<std::size_t>(gw) * gh);
    for (int y = 0; y < gh; ++y)
      for (int x = 0; x < gw; ++x) grid.emplace_back(ix0 + x - 0.5, iy0 + y - 0.5);
    if (camera.has_distortion()) {
      cv::undistortPoints(grid, rays_grid, cv::Mat(camera.K), cv::Mat(camera.dist), cv::noArray(), cv::noArray(),
                          cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
    } else {
      rays_grid.resize(grid.size());
      for (std::size_t i = 0; i < grid.size(); ++i) {
        const cv::Vec3d r = Kinv * cv::Vec3d(grid[i].x, grid[i].y, 1);
        rays_grid[i] = cv::Point2d(r[0] / r[2], r[1] / r[2]);
      }
    }
    std::vector<cv::Point2d> rays;
    for (int y = iy0; y <= iy1; ++y) {
      rays.clear();
      for (int x = ix0; x <= ix1; ++x) {
        const std::size_t g = static_cast<std::size_t>(y - iy0) * gw + (x - ix0);
        const cv::Point2d r00 = rays_grid[g], r01 = rays_grid[g + 1], r10 = rays_grid[g + gw], r11 = rays_grid[g + gw + 1];
        for (int sy = 0; sy < k_supersample; ++sy)
          for (int sx = 0; sx < k_supersample; ++sx) {
            const double fx = (sx + 0.5) / k_supersample, fy = (sy + 0.5) / k_supersample;
            rays.push_back((1 - fy) * ((1 - fx) * r00 + fx * r01) + fy * ((1 - fx) * r10 + fx * r11));
          }
      }
      std::size_t i = 0;
      for (int x = ix0; x <= ix1; ++x) {
        double sum = 0;
        int hits = 0;
        for (int k = 0; k < k_supersample * k_supersample; ++k, ++i) {
          const cv::Vec3d dir(rays[i].x, rays[i].y, 1);
          const double nd = n.dot(dir);
          if (std::abs(nd) < 1e-12) continue;
          const double lambda = nt / nd;
          if (lambda <= 0) continue;
          const cv::Vec3d X = Rt * (lambda * dir - m.pose.t);
          const double v = marker_value(m, X[0], X[1], occluder);
          if (v == -1) continue;
          sum += v == -2 ? occ_level : v;
          ++hits;
        }
        if (hits == 0) continue;
        const double cover = double(hits) / (k_supersample * k_supersample);
        const double level = d.black + (d.white - d.black) * (sum / hits);
        float& px = img.at<float>(y, x);
        px = float((1 - cover) * px + cover * level);
      }
    }
  }
  if (d.gradient != 0)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) img.at<float>(y, x) *= float(1 + d.gradient * (double(x) / w - 0.5));
  if (d.blur_sigma > 0) cv::GaussianBlur(img, img, cv::Size(0, 0), d.blur_sigma, d.blur_sigma, cv::BORDER_REPLICATE);
  if (d.noise_sigma > 0)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) img.at<float>(y, x) += float(d.noise_sigma * rng.normal());
  cv::Mat out;
  img.convertTo(out, CV_8U);  // rounds and saturates
  return out;
}

cv::Mat draw_marker(const Dictionary& dict, int id, int pixels_per_cell, int quiet_cells) {
  const MarkerArt a = binary_art(dict, id);
  const int cells = a.bits + 2, total = cells + 2 * quiet_cells;
  cv::Mat img(total * pixels_per_cell, total * pixels_per_cell, CV_8U, cv::Scalar(255));
  for (int r = 0; r < cells; ++r)
    for (int c = 0; c < cells; ++c) {
      bool white = false;
      if (r > 0 && c > 0 && r < cells - 1 && c < cells - 1) {
        const int bit = a.bits * a.bits - 1 - ((r - 1) * a.bits + (c - 1));
        white = (a.code >> bit) & 1u;
      }
      if (!white)
        img(cv::Rect((c + quiet_cells) * pixels_per_cell, (r + quiet_cells) * pixels_per_cell, pixels_per_cell,
                     pixels_per_cell)) = cv::Scalar(0);
    }
  return img;
}

Pose pose_facing(const CameraModel& camera, double u, double v, double distance, double tilt_deg, double axis_deg,
                 double roll_deg) {
  const cv::Vec3d r0 = camera.K.inv() * cv::Vec3d(u, v, 1);
  const cv::Vec3d ray = r0 / cv::norm(r0);
  // Facing the camera: marker z along -ray (towards the centre of projection), x as near
  // the camera's x as possible, y = z x x (up in the image).
  const cv::Vec3d z = -ray;
  cv::Vec3d x = cv::Vec3d(1, 0, 0) - z[0] * z;
  x /= cv::norm(x);
  const cv::Vec3d y = z.cross(x);
  const cv::Matx33d facing(x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]);
  const double a = axis_deg * M_PI / 180;
  const cv::Matx33d tilt = rotation_from_vector(cv::Vec3d(std::cos(a), std::sin(a), 0) * (tilt_deg * M_PI / 180));
  const cv::Matx33d roll = rotation_from_vector(cv::Vec3d(0, 0, roll_deg * M_PI / 180));
  Pose p;
  p.R = facing * tilt * roll;
  p.t = ray * distance;
  return p;
}

}  // namespace fest::markers

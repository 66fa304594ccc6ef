#include "markers/corner_refine.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "markers/line2d.hpp"

namespace fest::markers {

namespace {

// Bilinear grey value; the caller keeps (x, y) inside [0, w-1] x [0, h-1].
inline float sample(const cv::Mat& g, double x, double y) {
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, g.cols - 1), y1 = std::min(y0 + 1, g.rows - 1);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const uchar* r0 = g.ptr<uchar>(y0);
  const uchar* r1 = g.ptr<uchar>(y1);
  const float a = r0[x0] + fx * (r0[x1] - r0[x0]);
  const float b = r1[x0] + fx * (r1[x1] - r1[x0]);
  return a + fy * (b - a);
}

struct EdgePoint {
  cv::Point2d p;
  double w;
};

// Weighted total-least-squares line.
Line fit_line(const std::vector<EdgePoint>& pts) {
  double sw = 0, mx = 0, my = 0;
  for (const EdgePoint& e : pts) sw += e.w, mx += e.w * e.p.x, my += e.w * e.p.y;
  mx /= sw, my /= sw;
  double sxx = 0, sxy = 0, syy = 0;
  for (const EdgePoint& e : pts) {
    const double dx = e.p.x - mx, dy = e.p.y - my;
    sxx += e.w * dx * dx, sxy += e.w * dx * dy, syy += e.w * dy * dy;
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  return {cv::Point2d(mx, my), cv::Point2d(std::cos(angle), std::sin(angle))};
}

// Distorted pixels -> ideal pixels (the same K, no distortion).
void undistort_in_place(std::vector<EdgePoint>& pts, const CameraModel& cam) {
  std::vector<cv::Point2d> in, out;
  for (const EdgePoint& e : pts) in.push_back(e.p);
  cv::undistortPoints(in, out, cv::Mat(cam.K), cv::Mat(cam.dist), cv::noArray(), cv::Mat(cam.K),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i].p = out[i];
}

// Ideal pixels -> distorted pixels.
void distort_in_place(Corners& c, const CameraModel& cam) {
  const cv::Matx33d Kinv = cam.K.inv();
  std::vector<cv::Point3d> rays;
  for (const cv::Point2d& p : c) {
    const cv::Vec3d r = Kinv * cv::Vec3d(p.x, p.y, 1);
    rays.emplace_back(r[0] / r[2], r[1] / r[2], 1);
  }
  std::vector<cv::Point2d> out;
  cv::projectPoints(rays, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Mat(cam.K), cv::Mat(cam.dist), out);
  for (int i = 0; i < 4; ++i) c[i] = out[i];
}

}  // namespace

bool refine_corners(const cv::Mat& grey8, Corners& corners, int cells, const CameraModel* camera, int passes) {
  const bool distorted = camera && camera->has_distortion();
  const double w = grey8.cols - 1.001, h = grey8.rows - 1.001;
  for (int pass = 0; pass < passes; ++pass) {
    std::array<Line, 4> lines;
    for (int s = 0; s < 4; ++s) {
      const cv::Point2d a = corners[s], b = corners[(s + 1) % 4];
      const double len = cv::norm(b - a);
      if (len < 3) return false;
      const cv::Point2d dir = (b - a) / len;
      // Corners run clockwise on screen (y down): the outside is on the left of a->b,
      // i.e. along (dir.y, -dir.x).
      const cv::Point2d out(dir.y, -dir.x);
      const double cell = len / cells;
      const double reach = std::clamp(0.4 * cell, 1.0, pass == 0 ? 6.0 : 3.0);
      const double step = 0.25;
      const int half = static_cast<int>(std::ceil((reach + 1) / step));
      const int samples = std::clamp(static_cast<int>(len / 1.5), 6, 64);
      std::vector<EdgePoint> pts;
      std::vector<float> prof(2 * half + 1);
      for (int k = 0; k < samples; ++k) {
        const double t = 0.12 + 0.76 * (k + 0.5) / samples;
        const cv::Point2d base = a + t * len * dir;
        // Five parallel profiles half a pixel apart along the edge, averaged: the edge
        // is straight there, the noise is not.
        bool inside = true;
        for (int j = -half; j <= half && inside; ++j) {
          float sum = 0;
          for (int lane = -2; lane <= 2 && inside; ++lane) {
            const cv::Point2d q = base + (j * step) * out + (0.5 * lane) * dir;
            if (q.x < 0 || q.y < 0 || q.x > w || q.y > h) inside = false;
            else sum += sample(grey8, q.x, q.y);
          }
          prof[j + half] = sum / 5;
        }
        if (!inside) continue;
        // Derivative outward over 1.5 pixels (central difference at +-0.75 px: smoother
        // than the one-pixel difference, matched to blurred edges).
        const int lag = static_cast<int>(0.75 / step);
        int best = 0;
        double best_g = 0;
        std::vector<double> g(prof.size(), 0);
        for (int j = lag; j + lag < static_cast<int>(prof.size()); ++j) {
          g[j] = prof[j + lag] - prof[j - lag];
          const double dist = std::abs((j - half) * step);
          if (dist <= reach && g[j] > best_g) best_g = g[j], best = j;
        }
        if (best_g < 4 || best <= lag || best + lag >= static_cast<int>(prof.size()) - 1) continue;
        // Centroid of the derivative over +-1 px around its peak (less pixel-locking than
        // a parabola through bilinear samples).
        const int span = static_cast<int>(1.0 / step);
        double sw = 0, sj = 0;
        for (int j = std::max(lag, best - span); j <= std::min(static_cast<int>(prof.size()) - 1 - lag, best + span); ++j)
          if (g[j] > 0.2 * best_g) sw += g[j] - 0.2 * best_g, sj += (g[j] - 0.2 * best_g) * j;
        const double pos = (sj / sw - half) * step;
        pts.push_back({base + pos * out, best_g});
      }
      if (pts.size() < 4) return false;
      if (distorted) undistort_in_place(pts, *camera);
      Line line = fit_line(pts);
      // Drop points off the line (occluders, data cells, noise peaks) and fit again, twice:
      // first beyond a fixed bound, then beyond 3 robust sigmas (1.4826 MAD) of the rest.
      for (int round = 0; round < 2; ++round) {
        const cv::Point2d normal(-line.dir.y, line.dir.x);
        std::vector<double> res;
        for (const EdgePoint& e : pts) res.push_back(std::abs((e.p - line.point).dot(normal)));
        double bound = std::max(0.5, 0.15 * cell);
        if (round == 1) {
          std::vector<double> sorted = res;
          std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
          bound = std::min(bound, std::max(0.05, 3 * 1.4826 * sorted[sorted.size() / 2]));
        }
        std::vector<EdgePoint> kept;
        for (std::size_t k = 0; k < pts.size(); ++k)
          if (res[k] < bound) kept.push_back(pts[k]);
        if (kept.size() < 4) return false;
        if (kept.size() == pts.size()) break;
        pts = std::move(kept);
        line = fit_line(pts);
      }
      lines[s] = line;
    }
    Corners next;
    for (int c = 0; c < 4; ++c)
      if (!intersect(lines[(c + 3) % 4], lines[c], next[c])) return false;
    if (distorted) distort_in_place(next, *camera);
    // A corner that jumps by more than a cell means the fit followed something else.
    for (int c = 0; c < 4; ++c) {
      const double side = cv::norm(corners[(c + 1) % 4] - corners[c]);
      if (cv::norm(next[c] - corners[c]) > std::max(2.0, 0.5 * side / cells)) return false;
    }
    corners = next;
  }
  return true;
}

}  // namespace fest::markers

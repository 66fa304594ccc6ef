#include "markers/edge_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "markers/line2d.hpp"

namespace fest::markers {

namespace {

struct Pixel {
  cv::Point2d p;  // ideal pixel coordinates of the pixel centre
  double v;       // grey level
};

std::vector<cv::Point2d> to_ideal(const std::vector<cv::Point2d>& in, const CameraModel* cam) {
  if (!cam || !cam->has_distortion() || in.empty()) return in;
  std::vector<cv::Point2d> out;
  cv::undistortPoints(in, out, cv::Mat(cam->K), cv::Mat(cam->dist), cv::noArray(), cv::Mat(cam->K),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
  return out;
}

std::vector<cv::Point2d> to_distorted(const std::vector<cv::Point2d>& in, const CameraModel* cam) {
  if (!cam || !cam->has_distortion() || in.empty()) return in;
  const cv::Matx33d Kinv = cam->K.inv();
  std::vector<cv::Point3d> rays;
  for (const cv::Point2d& p : in) {
    const cv::Vec3d r = Kinv * cv::Vec3d(p.x, p.y, 1);
    rays.emplace_back(r[0] / r[2], r[1] / r[2], 1);
  }
  std::vector<cv::Point2d> out;
  cv::projectPoints(rays, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Mat(cam->K), cv::Mat(cam->dist), out);
  return out;
}

double distance_to_chord(cv::Point2d p, cv::Point2d a, cv::Point2d b) {
  const cv::Point2d d = b - a;
  return std::abs(d.x * (p.y - a.y) - d.y * (p.x - a.x)) / std::max(1e-12, cv::norm(d));
}

// The pixels that can fall in the band during the fit: within `reach` of the side in
// the (distorted) image, plus the bow of the distorted edge; their ideal coordinates.
std::vector<Pixel> candidate_pixels(const cv::Mat& g, cv::Point2d a, cv::Point2d b, cv::Point2d ia, cv::Point2d ib,
                                    double reach, const CameraModel* cam) {
  double bow = 0;
  if (cam && cam->has_distortion()) {
    std::vector<cv::Point2d> ideal;
    for (int k = 1; k < 8; ++k) ideal.push_back(ia + (ib - ia) * (k / 8.0));
    for (const cv::Point2d& p : to_distorted(ideal, cam)) bow = std::max(bow, distance_to_chord(p, a, b));
  }
  reach += bow;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x, b.x) - reach)));
  const int x1 = std::min(g.cols - 1, static_cast<int>(std::ceil(std::max(a.x, b.x) + reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y, b.y) - reach)));
  const int y1 = std::min(g.rows - 1, static_cast<int>(std::ceil(std::max(a.y, b.y) + reach)));
  const cv::Point2d d = b - a;
  const double len = cv::norm(d);
  std::vector<cv::Point2d> pos;
  std::vector<double> val;
  for (int y = y0; y <= y1; ++y) {
    const uchar* row = g.ptr<uchar>(y);
    for (int x = x0; x <= x1; ++x) {
      const cv::Point2d q(x - a.x, y - a.y);
      const double along = q.dot(d) / len;
      if (along < -reach || along > len + reach || std::abs(d.x * q.y - d.y * q.x) / len > reach) continue;
      pos.emplace_back(x, y);
      val.push_back(row[x]);
    }
  }
  const std::vector<cv::Point2d> ideal = to_ideal(pos, cam);
  std::vector<Pixel> out(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) out[i] = {ideal[i], val[i]};
  return out;
}

// Gauss-Newton fit of the blurred step to one side, a -> b in ideal pixels (clockwise on
// screen, so the light outside lies on the left: along (dir.y, -dir.x)).
bool fit_side(const std::vector<Pixel>& pixels, cv::Point2d a, cv::Point2d b, double band,
              const EdgeModelOptions& o, double noise_sigma, Line& out) {
  const double len = cv::norm(b - a);
  cv::Point2d mid = 0.5 * (a + b), dir = (b - a) / len;
  const double half_span = (0.5 - o.end_margin) * len;
  double A0 = 0, A1 = 0, B0 = 0, B1 = 0, s = 1.0, rms = 1e300;
  bool levels_known = false;
  for (int it = 0; it < o.iterations; ++it) {
    const cv::Point2d nrm(dir.y, -dir.x);
    if (!levels_known) {
      double sa = 0, sb = 0;
      int na = 0, nb = 0;
      for (const Pixel& px : pixels) {
        const cv::Point2d q = px.p - mid;
        const double d = q.dot(nrm);
        if (std::abs(q.dot(dir)) > half_span || std::abs(d) > band) continue;
        if (d < -0.5 * band) sa += px.v, ++na;
        else if (d > 0.5 * band) sb += px.v, ++nb;
      }
      if (na == 0 || nb == 0) return false;
      A0 = sa / na, B0 = sb / nb;
      levels_known = true;
    }
    // Levels linear along the side only when the band reaches well past the blur: in a
    // narrow band a level ramp and a turn of the line look alike, and fitting both costs
    // more in noise than the ramp (a few per cent of contrast on a small marker) biases.
    const bool linear = it >= 2 && band >= o.linear_levels_ratio * s;
    const int n = linear ? 7 : 5;  // rho, theta, A0, B0, s [, A1, B1]
    cv::Matx<double, 7, 7> H = cv::Matx<double, 7, 7>::zeros();
    cv::Vec<double, 7> grad = cv::Vec<double, 7>::all(0);
    double sse = 0;
    int used = 0;
    for (const Pixel& px : pixels) {
      const cv::Point2d q = px.p - mid;
      const double u = q.dot(dir), d = q.dot(nrm);
      if (std::abs(u) > half_span || std::abs(d) > band) continue;
      const double t = u / len, z = d / s;
      const double Phi = 0.5 * std::erfc(-z * M_SQRT1_2);
      const double phi = std::exp(-0.5 * z * z) * (0.5 * M_2_SQRTPI * M_SQRT1_2);
      const double A = A0 + A1 * t, B = B0 + B1 * t;
      const double r = px.v - (A + (B - A) * Phi);
      const double dm_dd = (B - A) * phi / s;
      // d moves by -drho when the line shifts outward, by +u dtheta when it turns
      // (dir <- R(dtheta) dir): the model's derivatives (docs/markerpose.md §2.4).
      const cv::Vec<double, 7> J(-dm_dd, dm_dd * u, 1 - Phi, Phi, -dm_dd * z, (1 - Phi) * t, Phi * t);
      for (int i = 0; i < n; ++i) {
        grad[i] += J[i] * r;
        for (int j = 0; j <= i; ++j) H(i, j) += J[i] * J[j];
      }
      sse += r * r;
      ++used;
    }
    if (used < 3 * n) return false;
    rms = std::sqrt(sse / used);
    cv::Mat Hn(n, n, CV_64F), gn(n, 1, CV_64F), step;
    for (int i = 0; i < n; ++i) {
      gn.at<double>(i) = grad[i];
      for (int j = 0; j <= i; ++j) Hn.at<double>(i, j) = Hn.at<double>(j, i) = H(i, j);
      Hn.at<double>(i, i) *= 1 + 1e-6;  // a touch of Levenberg damping
    }
    if (!cv::solve(Hn, gn, step, cv::DECOMP_CHOLESKY)) return false;
    const double drho = step.at<double>(0), dth = std::clamp(step.at<double>(1), -0.1, 0.1);
    mid += std::clamp(drho, -1.0, 1.0) * nrm;
    dir = cv::Point2d(dir.x * std::cos(dth) - dir.y * std::sin(dth), dir.x * std::sin(dth) + dir.y * std::cos(dth));
    A0 += step.at<double>(2), B0 += step.at<double>(3);
    s = std::clamp(s + step.at<double>(4), 0.3, 4.0);
    if (linear) A1 += step.at<double>(5), B1 += step.at<double>(6);
    if (it >= 3 && std::abs(drho) < 1e-4 && std::abs(dth) < 1e-6) break;
  }
  if (!(B0 - A0 > 4) || rms > 3 * noise_sigma + 3) return false;
  out = {mid, dir};
  return true;
}

}  // namespace

bool fit_edge_model(const cv::Mat& grey8, Corners& corners, int cells, const CameraModel* camera, double noise_sigma,
                    const EdgeModelOptions& o) {
  CV_Assert(grey8.type() == CV_8UC1);
  const std::vector<cv::Point2d> ideal = to_ideal({corners.begin(), corners.end()}, camera);
  double side = 0;
  for (int k = 0; k < 4; ++k) side += cv::norm(ideal[(k + 1) % 4] - ideal[k]) / 4;
  const double cell = side / cells;
  // Below about 2 px a cell, the band of half a cell holds no plateau on either side
  // and the next edges fall inside it: the edge-point corners are kept.
  if (cell < 1.75) return false;
  const double band = std::clamp(o.band_cells * cell, o.band_min_px, o.band_max_px);
  std::array<Line, 4> lines;
  for (int s = 0; s < 4; ++s) {
    const int e = (s + 1) % 4;
    if (cv::norm(ideal[e] - ideal[s]) < 4) return false;
    const std::vector<Pixel> px = candidate_pixels(grey8, corners[s], corners[e], ideal[s], ideal[e], band + 2, camera);
    if (!fit_side(px, ideal[s], ideal[e], band, o, noise_sigma, lines[s])) return false;
  }
  std::vector<cv::Point2d> next(4);
  for (int c = 0; c < 4; ++c)
    if (!intersect(lines[(c + 3) % 4], lines[c], next[c])) return false;
  next = to_distorted(next, camera);
  // The start is already within a fraction of a pixel: a larger jump means the model
  // locked onto another edge.
  for (int c = 0; c < 4; ++c)
    if (cv::norm(next[c] - corners[c]) > std::max(0.75, 0.3 * cell)) return false;
  for (int c = 0; c < 4; ++c) corners[c] = next[c];
  return true;
}

}  // namespace fest::markers

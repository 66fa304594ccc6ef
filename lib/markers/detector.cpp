#include "markers/detector.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "markers/corner_refine.hpp"
#include "markers/edge_model.hpp"

namespace fest::markers {

namespace {

cv::Matx33d square_to_quad(const Corners& c, double n) {
  const cv::Point2f src[4] = {{0, 0}, {float(n), 0}, {float(n), float(n)}, {0, float(n)}};
  const cv::Point2f dst[4] = {cv::Point2f(c[0]), cv::Point2f(c[1]), cv::Point2f(c[2]), cv::Point2f(c[3])};
  return cv::Matx33d(cv::getPerspectiveTransform(src, dst));
}

float bilinear(const cv::Mat& g, double x, double y) {
  x = std::clamp(x, 0.0, g.cols - 1.001);
  y = std::clamp(y, 0.0, g.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float fx = float(x - x0), fy = float(y - y0);
  const uchar* r0 = g.ptr<uchar>(y0);
  const uchar* r1 = g.ptr<uchar>(y0 + 1);
  const float a = r0[x0] + fx * (r0[x0 + 1] - r0[x0]);
  const float b = r1[x0] + fx * (r1[x0 + 1] - r1[x0]);
  return a + fy * (b - a);
}

cv::Point2d map(const cv::Matx33d& H, double x, double y) {
  const double w = H(2, 0) * x + H(2, 1) * y + H(2, 2);
  return {(H(0, 0) * x + H(0, 1) * y + H(0, 2)) / w, (H(1, 0) * x + H(1, 1) * y + H(1, 2)) / w};
}

// Otsu's split of a few values: the threshold maximising the between-class variance.
double otsu(std::vector<float> v, double& dark_mean, double& light_mean) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  double total = 0;
  for (float x : v) total += x;
  double best = -1, threshold = v[n / 2], left = 0;
  dark_mean = light_mean = v[n / 2];
  for (std::size_t k = 1; k < n; ++k) {
    left += v[k - 1];
    const double m0 = left / k, m1 = (total - left) / (n - k);
    const double between = double(k) * double(n - k) * (m1 - m0) * (m1 - m0);
    if (between > best) {
      best = between;
      threshold = 0.5 * (v[k - 1] + v[k]);
      dark_mean = m0, light_mean = m1;
    }
  }
  return threshold;
}

Corners rotate_corners(const Corners& c, int k) {
  Corners out;
  for (int i = 0; i < 4; ++i) out[i] = c[(i + k) % 4];
  return out;
}

bool same_place(const Corners& a, const Corners& b) {
  double d = 0, side = 0;
  for (int i = 0; i < 4; ++i) d += cv::norm(a[i] - b[i]), side += cv::norm(a[(i + 1) % 4] - a[i]);
  return d / 4 < 0.1 * side / 4;
}

// Binary markers: n x n data cells inside a one-cell black border.
bool identify_binary(const cv::Mat& grey8, const Corners& quad, const DetectorOptions& o, Detection& out) {
  const Dictionary& dict = *o.dictionary;
  const int n = dict.bits, cells = n + 2;
  const std::vector<float> v = sample_cells(grey8, quad, cells);
  double dark, light;
  const double threshold = otsu(v, dark, light);
  if (light - dark < o.min_contrast) return false;
  int border_white = 0, border = 0;
  std::uint64_t code = 0, uncertain = 0;
  for (int r = 0; r < cells; ++r)
    for (int c = 0; c < cells; ++c) {
      const bool white = v[r * cells + c] > threshold;
      if (r == 0 || c == 0 || r == cells - 1 || c == cells - 1) {
        ++border;
        border_white += white;
      } else {
        code = (code << 1) | (white ? 1u : 0u);
        // A printed cell is black or white: a grey one (occluder, texture) is an erasure.
        uncertain = (uncertain << 1) | (std::abs(v[r * cells + c] - threshold) < o.uncertain_margin * (light - dark));
      }
    }
  if (border_white > o.max_border_errors * border) return false;
  const Decoded d = decode(dict, code, uncertain);
  if (d.id < 0) return false;
  out.id = d.id;
  out.bit_errors = d.bit_errors;
  out.corners = rotate_corners(quad, d.rotation);
  return true;
}

// Pattern markers: the picture fills the middle half of the square (border = side / 4).
bool identify_pattern(const cv::Mat& grey8, const Corners& quad, const DetectorOptions& o, Detection& out) {
  // Border check on a 4 x 4 cell layout: the 12 outer cells must be dark.
  const std::vector<float> v = sample_cells(grey8, quad, 4);
  const cv::Matx33d H = square_to_quad(quad, 4.0);
  std::vector<float> s(k_pattern_samples * k_pattern_samples);
  for (int r = 0; r < k_pattern_samples; ++r)
    for (int c = 0; c < k_pattern_samples; ++c) {
      const cv::Point2d p = map(H, 1 + 2.0 * (c + 0.5) / k_pattern_samples, 1 + 2.0 * (r + 0.5) / k_pattern_samples);
      s[r * k_pattern_samples + c] = bilinear(grey8, p.x, p.y);
    }
  double border_mean = 0;
  int border_light = 0;
  float inner_max = 0;
  for (float x : s) inner_max = std::max(inner_max, x);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (r == 0 || c == 0 || r == 3 || c == 3) border_mean += v[r * 4 + c] / 12.0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if ((r == 0 || c == 0 || r == 3 || c == 3) && v[r * 4 + c] > 0.5 * (border_mean + inner_max)) ++border_light;
  if (inner_max - border_mean < o.min_contrast || border_light > o.max_border_errors * 12) return false;
  if (!normalise_samples(s)) return false;
  const PatternMatch m = match_pattern(*o.patterns, s, o.min_pattern_ncc);
  if (m.index < 0) return false;
  out.id = m.index;
  out.score = m.ncc;
  out.corners = rotate_corners(quad, m.rotation);
  return true;
}

}  // namespace

double image_noise(const cv::Mat& grey8) {
  // Robust noise sigma from horizontal neighbour differences on every 4th row: the median
  // ignores the few differences that straddle edges; d = n1 - n2 has sigma sqrt(2) sigma_n.
  std::array<std::size_t, 256> hist{};
  std::size_t count = 0;
  for (int y = 0; y < grey8.rows; y += 4) {
    const uchar* row = grey8.ptr<uchar>(y);
    for (int x = 0; x + 1 < grey8.cols; ++x, ++count) ++hist[static_cast<std::size_t>(std::abs(row[x + 1] - row[x]))];
  }
  if (count == 0) return 0;
  std::size_t seen = 0;
  int median = 0;
  while (median < 255 && (seen += hist[static_cast<std::size_t>(median)]) < (count + 1) / 2) ++median;
  return 1.4826 * median / std::sqrt(2.0);
}

std::vector<float> sample_cells(const cv::Mat& grey8, const Corners& corners, int n) {
  const cv::Matx33d H = square_to_quad(corners, n);
  std::vector<float> v(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      float sum = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const cv::Point2d p = map(H, c + 0.25 + 0.25 * j, r + 0.25 + 0.25 * i);
          sum += bilinear(grey8, p.x, p.y);
        }
      v[r * n + c] = sum / 9;
    }
  return v;
}

std::vector<Detection> detect_markers(const cv::Mat& grey8, const DetectorOptions& o) {
  if (!o.dictionary && (!o.patterns || o.patterns->empty()))
    throw bad_input("marker detection needs a dictionary or at least one pattern");
  CV_Assert(grey8.type() == CV_8UC1);
  const int cells = o.dictionary ? o.dictionary->bits + 2 : 4;
  std::vector<Detection> found;
  // In a noisy image the edges are located on a lightly smoothed copy: the noise of single
  // pixels averages out, and a symmetric blur moves no edge. On a clean image smoothing
  // only widens the edge, so it is skipped.
  const double noise = image_noise(grey8);
  const double sigma = o.edge_sigma >= 0 ? o.edge_sigma : (noise > 2.5 ? 0.8 : 0.0);
  cv::Mat smooth;
  if (sigma > 0) cv::GaussianBlur(grey8, smooth, cv::Size(0, 0), sigma);
  else smooth = grey8;
  for (Corners quad : find_quads(grey8, o.quads)) {
    // A quad whose edges cannot be fitted (tiny, or an edge hidden) keeps its polygon
    // corners: identified still, with a coarser pose.
    if (o.refine_corners) {
      Corners refined = quad;
      if (refine_corners(smooth, refined, cells, o.camera)) quad = refined;
    }
    Detection d;
    const bool ok = o.dictionary ? identify_binary(grey8, quad, o, d) : identify_pattern(grey8, quad, o, d);
    if (!ok) continue;
    // The edge points located the sides well enough to read the code; the blurred-step
    // model over every pixel along the sides (on the unsmoothed image) places them
    // closer, for markers only (docs/markerpose.md §2.4).
    if (o.refine_corners && o.edge_model) fit_edge_model(grey8, d.corners, cells, o.camera, noise);
    bool duplicate = false;
    for (Detection& f : found)
      if (f.id == d.id && same_place(f.corners, d.corners)) {
        duplicate = true;
        if (d.bit_errors < f.bit_errors || d.score > f.score) f = d;
      }
    if (!duplicate) found.push_back(d);
  }
  std::sort(found.begin(), found.end(), [](const Detection& a, const Detection& b) {
    if (a.id != b.id) return a.id < b.id;
    if (a.corners[0].y != b.corners[0].y) return a.corners[0].y < b.corners[0].y;
    return a.corners[0].x < b.corners[0].x;
  });
  return found;
}

}  // namespace fest::markers

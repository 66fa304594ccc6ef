#include "markers/pattern.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fest::markers {

namespace {

std::vector<float> rotate_ccw(const std::vector<float>& s) {
  const int n = k_pattern_samples;
  std::vector<float> out(s.size());
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) out[r * n + c] = s[c * n + (n - 1 - r)];
  return out;
}

}  // namespace

bool normalise_samples(std::vector<float>& s) {
  double mean = 0;
  for (float v : s) mean += v;
  mean /= static_cast<double>(s.size());
  double norm = 0;
  for (float& v : s) {
    v = static_cast<float>(v - mean);
    norm += double(v) * v;
  }
  norm = std::sqrt(norm);
  if (norm < 1e-3 * static_cast<double>(s.size())) return false;
  for (float& v : s) v = static_cast<float>(v / norm);
  return true;
}

PatternTemplate make_pattern(const cv::Mat& picture, const std::string& name) {
  if (picture.empty() || picture.type() != CV_8UC1) throw bad_input("pattern '{}': empty or not 8-bit grey", name);
  cv::Mat small;
  cv::resize(picture, small, cv::Size(k_pattern_samples, k_pattern_samples), 0, 0, cv::INTER_AREA);
  std::vector<float> s(k_pattern_samples * k_pattern_samples);
  for (int r = 0; r < k_pattern_samples; ++r)
    for (int c = 0; c < k_pattern_samples; ++c) s[r * k_pattern_samples + c] = small.at<uchar>(r, c);
  if (!normalise_samples(s)) throw bad_input("pattern '{}' is flat: nothing to match", name);
  PatternTemplate t;
  t.name = name;
  t.rotations[0] = s;
  for (int k = 1; k < 4; ++k) t.rotations[k] = rotate_ccw(t.rotations[k - 1]);
  return t;
}

// The rotation reported is the one of dictionary.hpp's Decoded: how often the sampled
// grid must turn ccw to equal the template.
PatternMatch match_pattern(const std::vector<PatternTemplate>& patterns, const std::vector<float>& samples,
                           double min_ncc) {
  PatternMatch best;
  for (std::size_t i = 0; i < patterns.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      double dot = 0;
      const std::vector<float>& t = patterns[i].rotations[k];
      for (std::size_t j = 0; j < t.size(); ++j) dot += double(t[j]) * samples[j];
      if (dot > best.ncc) {
        best.ncc = dot;
        best.index = static_cast<int>(i);
        // samples == template rotated ccw k  <=>  samples rotated ccw (4-k) == template.
        best.rotation = (4 - k) % 4;
      }
    }
  if (best.ncc < min_ncc) best.index = -1;
  return best;
}

}  // namespace fest::markers

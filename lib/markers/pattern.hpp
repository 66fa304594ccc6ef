#pragma once
// ARToolKit-style pattern markers (Kato & Billinghurst 1999; docs/markerpose.md §3.2):
// a black square border a quarter of the side wide around an arbitrary picture. The
// picture is unwarped to 16 x 16 samples and compared by normalised cross-correlation
// with every template in its four rotations; the best match above a threshold wins.

#include <array>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace fest::markers {

constexpr int k_pattern_samples = 16;

struct PatternTemplate {
  std::string name;
  // Zero-mean, unit-norm 16 x 16 samples, rotated ccw 0..3 times.
  std::array<std::vector<float>, 4> rotations;
};

// From the picture inside the border (any size, grey 8-bit; resampled by area averaging).
// Throws fest::Error (bad_input) for an empty or flat picture (nothing to correlate).
PatternTemplate make_pattern(const cv::Mat& picture_grey8, const std::string& name);

// Zero-mean unit-norm copy of 16 x 16 samples; false when they are flat.
bool normalise_samples(std::vector<float>& samples);

struct PatternMatch {
  int index = -1;  // -1: nothing above the threshold
  int rotation = 0;
  double ncc = 0;
};

PatternMatch match_pattern(const std::vector<PatternTemplate>& patterns, const std::vector<float>& samples,
                           double min_ncc);

}  // namespace fest::markers

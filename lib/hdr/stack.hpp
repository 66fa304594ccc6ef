#pragma once
// An exposure series of one static scene: 8-bit images and their exposure times.
// Shared by response recovery and merging (docs/hdrmerge.md §4).

#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace fest::hdr {

constexpr int kCodes = 256;  // 8-bit pixel values Z = 0..255
constexpr int kZmin = 0;
constexpr int kZmax = 255;

struct ExposureStack {
  std::vector<cv::Mat> images;  // CV_8UC1 or CV_8UC3, all the same size and type
  std::vector<double> times;    // exposure time of each image, seconds, strictly increasing
};

// Throws fest::Error(bad_input) naming what is wrong: fewer than two exposures, a count
// mismatch, sizes or channel counts that differ, depths other than 8 bits, times that
// are not positive, finite and strictly increasing.
void validate_stack(const ExposureStack& stack);

// Debevec-Malik hat weight: z - Zmin below the middle of the range, Zmax - z above it;
// zero at both ends, so black and saturated values carry no information.
constexpr double hat_weight(int z) {
  return 2 * z <= kZmin + kZmax ? double(z - kZmin) : double(kZmax - z);
}
constexpr double kMaxHatWeight = hat_weight((kZmin + kZmax) / 2);

}  // namespace fest::hdr

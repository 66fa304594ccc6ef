#pragma once
// Image error statistics per channel: RMSE, PSNR and maximum absolute difference.

#include <vector>

#include <opencv2/core.hpp>

namespace fest::compare {

struct ChannelError {
  double rmse = 0;
  double psnr = 0;     // +inf when identical
  double max_abs = 0;  // +inf when exactly one of two pixels is NaN
};

struct ImageError {
  std::vector<ChannelError> channels;
  ChannelError all;  // over every channel together
  double peak = 1;   // the signal peak used by PSNR
};

// The peak value of a depth: 255 for 8-bit, 65535 for 16-bit, 1 for float.
double default_peak(int depth);

// Both images must have the same size, depth and channel count (throws
// Status::failure otherwise: a difference, not bad input). peak <= 0 picks default_peak.
ImageError image_error(const cv::Mat& a, const cv::Mat& b, double peak = 0);

}  // namespace fest::compare

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

// When exactly one image has an alpha channel (RGB against RGBA, grey against grey +
// alpha), the other is taken as opaque: the colour channels are compared and the alpha
// channel is measured against opaque on its own.
struct AlphaAgainstOpaque {
  bool measured = false;
  int image = 0;         // 1 or 2: which image has the alpha channel
  double max_abs = 0;    // max |alpha - peak| over all pixels
  double min_alpha = 0;  // the least alpha value found
};

struct ImageError {
  std::vector<ChannelError> channels;  // the compared channels (colour only, see above)
  ChannelError all;  // over every compared channel together
  double peak = 1;   // the signal peak used by PSNR
  AlphaAgainstOpaque alpha;
};

// The peak value of a depth: 255 for 8-bit, 65535 for 16-bit, 1 for float.
double default_peak(int depth);

// Both images must have the same size and depth, and the same channel count or the
// same colour channels with alpha in only one (throws Status::failure otherwise: a
// difference, not bad input). peak <= 0 picks default_peak.
ImageError image_error(const cv::Mat& a, const cv::Mat& b, double peak = 0);

}  // namespace fest::compare

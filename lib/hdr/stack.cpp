#include "hdr/stack.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::hdr {

void validate_stack(const ExposureStack& stack) {
  const std::size_t p = stack.images.size();
  if (p != stack.times.size())
    throw bad_input("{} images but {} exposure times", p, stack.times.size());
  if (p < 2) throw bad_input("an exposure series needs at least 2 images, got {}", p);
  const cv::Mat& first = stack.images.front();
  for (std::size_t j = 0; j < p; ++j) {
    const cv::Mat& m = stack.images[j];
    if (m.depth() != CV_8U)
      throw bad_input("image {} is not 8-bit (response recovery works on 8-bit values)", j + 1);
    if (m.channels() != 1 && m.channels() != 3)
      throw bad_input("image {} has {} channels, expected 1 or 3", j + 1, m.channels());
    if (m.empty()) throw bad_input("image {} is empty", j + 1);
    if (m.size() != first.size() || m.channels() != first.channels())
      throw bad_input("image {} is {}x{}x{}, image 1 is {}x{}x{}", j + 1, m.cols, m.rows, m.channels(), first.cols,
                      first.rows, first.channels());
    const double t = stack.times[j];
    if (!(std::isfinite(t) && t > 0)) throw bad_input("exposure time {} is {}, must be positive", j + 1, t);
    if (j > 0 && !(t > stack.times[j - 1]))
      throw bad_input("exposure times must increase: time {} ({}) follows {}", j + 1, t, stack.times[j - 1]);
  }
}

}  // namespace fest::hdr

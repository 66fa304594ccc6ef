#pragma once
// Error statistics of paired values -- RMSE, PSNR and the largest absolute difference --
// the one implementation the image comparisons share (fcompare's lib/compare, resample's
// metrics in lib/sampling).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fest {

// 20 log10(peak / rmse) in dB; +inf for identical signals (rmse 0, or NaN from no data).
inline double psnr_db(double rmse, double peak) {
  if (!(rmse > 0)) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(peak / rmse);
}

// Absolute differences added one at a time.
struct ErrorAccumulator {
  double sum_sq = 0;
  double max_abs = 0;
  std::int64_t n = 0;

  void add(double abs_difference) {
    max_abs = std::max(max_abs, abs_difference);
    sum_sq += abs_difference * abs_difference;
    ++n;
  }
  // Another accumulator's differences after these (partial sums combined in a fixed
  // order keep results independent of how the work was split).
  void merge(const ErrorAccumulator& other) {
    max_abs = std::max(max_abs, other.max_abs);
    sum_sq += other.sum_sq;
    n += other.n;
  }
  double rmse() const { return n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0; }
  double psnr(double peak) const { return psnr_db(rmse(), peak); }
};

}  // namespace fest

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "compare/image_compare.hpp"
#include "core/error.hpp"
#include "core/error_stats.hpp"

namespace fest::compare {

namespace {

// lib/core's accumulator, with NaN = NaN a match and NaN against a number an infinite difference.
struct Accumulator {
  ErrorAccumulator errors;
  void add(double x, double y) {
    if (std::isnan(x) || std::isnan(y))
      errors.add((std::isnan(x) && std::isnan(y)) ? 0.0 : std::numeric_limits<double>::infinity());
    else
      errors.add(std::abs(x - y));
  }
  ChannelError result(double peak) const {
    ChannelError e;
    e.max_abs = errors.max_abs;
    e.rmse = errors.rmse();
    e.psnr = psnr_db(e.rmse, peak);
    return e;
  }
};

}  // namespace

double default_peak(int depth) {
  switch (depth) {
    case CV_8U: return 255.0;
    case CV_16U: return 65535.0;
    default: return 1.0;
  }
}

ImageError image_error(const cv::Mat& a, const cv::Mat& b, double peak) {
  if (a.size() != b.size())
    throw runtime_failure("image sizes differ: {}x{} and {}x{}", a.cols, a.rows, b.cols, b.rows);
  if (a.depth() != b.depth()) throw runtime_failure("sample depths differ");
  const int ca = a.channels(), cb = b.channels();
  // Alpha in one image only: grey (1) against grey+alpha (2), colour (3) against RGBA (4).
  const bool one_alpha = std::min(ca, cb) % 2 == 1 && std::max(ca, cb) == std::min(ca, cb) + 1;
  if (ca != cb && !one_alpha) throw runtime_failure("channel counts differ: {} and {}", ca, cb);
  ImageError out;
  out.peak = peak > 0 ? peak : default_peak(a.depth());
  const int channels = std::min(ca, cb);
  cv::Mat da, db;
  a.convertTo(da, CV_64F);
  b.convertTo(db, CV_64F);
  std::vector<Accumulator> per(static_cast<std::size_t>(channels));
  Accumulator all;
  if (ca != cb) {
    out.alpha.measured = true;
    out.alpha.image = ca > cb ? 1 : 2;
    out.alpha.min_alpha = std::numeric_limits<double>::infinity();
  }
  for (int y = 0; y < da.rows; ++y) {
    const double* pa = da.ptr<double>(y);
    const double* pb = db.ptr<double>(y);
    for (int x = 0; x < da.cols; ++x) {
      const double* qa = pa + static_cast<std::ptrdiff_t>(x) * ca;
      const double* qb = pb + static_cast<std::ptrdiff_t>(x) * cb;
      for (int c = 0; c < channels; ++c) {
        per[static_cast<std::size_t>(c)].add(qa[c], qb[c]);
        all.add(qa[c], qb[c]);
      }
      if (out.alpha.measured) {
        const double alpha = ca > cb ? qa[channels] : qb[channels];
        out.alpha.max_abs = std::max(out.alpha.max_abs, std::abs(alpha - out.peak));
        out.alpha.min_alpha = std::min(out.alpha.min_alpha, alpha);
      }
    }
  }
  for (const Accumulator& acc : per) out.channels.push_back(acc.result(out.peak));
  out.all = all.result(out.peak);
  return out;
}

}  // namespace fest::compare

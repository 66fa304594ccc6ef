#include "hdr/robertson.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"

namespace fest::hdr {
namespace {

double bump(int z) {
  // Values within 4 DN of the ends are biased by clipping once there is noise (the
  // clipped half of the noise is missing), and the t^2 weighting of the radiance step
  // would let the near-saturated longest exposures dominate: they get no weight.
  if (z < kZmin + 4 || z > kZmax - 4) return 0;
  const double mid = 0.5 * (kZmin + kZmax), d = (z - mid) / (mid - kZmin);
  return std::exp(-4 * d * d);
}

}  // namespace

Response recover_response_robertson(const ExposureStack& stack, const RobertsonOptions& options) {
  validate_stack(stack);
  if (options.iterations < 1) throw usage_error("Robertson: iterations must be positive, got {}", options.iterations);
  if (!(options.threshold >= 0)) throw usage_error("Robertson: threshold must not be negative");
  if (options.max_pixels < 1) throw usage_error("Robertson: max_pixels must be positive");
  const cv::Mat& first = stack.images.front();
  const int p = int(stack.images.size()), channels = first.channels();
  // The pixels used: a regular grid of at most max_pixels.
  const double step = std::max(1.0, std::sqrt(double(first.total()) / options.max_pixels));
  std::vector<std::size_t> pixels;
  for (double y = 0; y < first.rows; y += step)
    for (double x = 0; x < first.cols; x += step) pixels.push_back(std::size_t(y) * std::size_t(first.cols) + std::size_t(x));
  std::array<double, kCodes> weight{};
  for (int z = 0; z < kCodes; ++z) weight[std::size_t(z)] = bump(z);
  const int mid = (kZmin + kZmax + 1) / 2;
  Response response;
  for (int c = 0; c < channels; ++c) {
    auto value = [&](int j, std::size_t pixel) {
      return stack.images[std::size_t(j)].ptr<std::uint8_t>()[pixel * std::size_t(channels) + std::size_t(c)];
    };
    // Start from a linear response, I(z) = z / 128 (z = 0 kept positive).
    std::array<double, kCodes> inverse{};
    for (int z = 0; z < kCodes; ++z) inverse[std::size_t(z)] = std::max(z, 1) / double(mid);
    std::vector<double> radiance(pixels.size());
    for (int round = 0; round < options.iterations; ++round) {
      for (std::size_t i = 0; i < pixels.size(); ++i) {
        double num = 0, den = 0;
        for (int j = 0; j < p; ++j) {
          const int z = value(j, pixels[i]);
          const double t = stack.times[std::size_t(j)];
          num += weight[std::size_t(z)] * t * inverse[std::size_t(z)];
          den += weight[std::size_t(z)] * t * t;
        }
        radiance[i] = den > 0 ? num / den : 0;
      }
      std::array<double, kCodes> sum{};
      std::array<std::size_t, kCodes> count{};
      for (std::size_t i = 0; i < pixels.size(); ++i) {
        if (radiance[i] <= 0) continue;  // seen only black or saturated: no information
        for (int j = 0; j < p; ++j) {
          const int z = value(j, pixels[i]);
          sum[std::size_t(z)] += stack.times[std::size_t(j)] * radiance[i];
          ++count[std::size_t(z)];
        }
      }
      std::array<double, kCodes> next = inverse;  // unobserved codes keep their value
      for (int z = 0; z < kCodes; ++z)
        if (count[std::size_t(z)] > 0 && sum[std::size_t(z)] > 0) next[std::size_t(z)] = sum[std::size_t(z)] / double(count[std::size_t(z)]);
      if (!(next[std::size_t(mid)] > 0))
        throw bad_input("Robertson: value {} never observed in a usable pixel of channel {}", mid, c + 1);
      const double scale = next[std::size_t(mid)];
      double change = 0;
      int observed = 0;
      for (int z = 0; z < kCodes; ++z) {
        next[std::size_t(z)] /= scale;
        if (count[std::size_t(z)] > 0) {
          const double d = std::log(next[std::size_t(z)] / inverse[std::size_t(z)]);
          change += d * d;
          ++observed;
        }
      }
      inverse = next;
      if (std::sqrt(change / std::max(observed, 1)) < options.threshold) break;
    }
    Curve g{};
    for (int z = 0; z < kCodes; ++z) g[std::size_t(z)] = std::log(inverse[std::size_t(z)]);
    g[std::size_t(mid)] = 0;
    // The unweighted codes at the ends are not estimated (only averaged over biased
    // observations); continue the curve there with the slope of its last weighted codes,
    // so a merge that gives them a little weight is not thrown off.
    int lo = 0, hi = kCodes - 1;
    while (weight[std::size_t(lo)] == 0) ++lo;
    while (weight[std::size_t(hi)] == 0) --hi;
    for (int z = lo - 1; z >= 0; --z) g[std::size_t(z)] = g[std::size_t(z + 1)] - (g[std::size_t(lo + 1)] - g[std::size_t(lo)]);
    for (int z = hi + 1; z < kCodes; ++z) g[std::size_t(z)] = g[std::size_t(z - 1)] + (g[std::size_t(hi)] - g[std::size_t(hi - 1)]);
    response.g.push_back(g);
  }
  return response;
}

}  // namespace fest::hdr

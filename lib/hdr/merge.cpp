#include "hdr/merge.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <thread>

#include "core/error.hpp"

namespace fest::hdr {
namespace {

// Per channel and exposure: w(z) (g(z) - ln dt_j); per channel: w(z). Float tables keep
// the inner loop to two loads and two adds per exposure.
struct Tables {
  std::vector<std::array<float, kCodes>> weighted_log;  // [c * P + j]
  std::array<float, kCodes> weight{};
};

// One row at a time, exposures outermost: each pass streams one 8-bit row and adds two
// table lookups per sample into float accumulators; the exponential runs once per row
// through OpenCV's vectorised cv::exp.
void merge_rows(const ExposureStack& stack, const Response& response, const Tables& tables, int row_begin,
                int row_end, MergeResult& out, const ProgressFn& progress = {}) {
  const int p = int(stack.images.size());
  const int channels = response.channels();
  const int width = stack.images.front().cols;
  const std::size_t samples = std::size_t(width) * std::size_t(channels);
  const double log_short = std::log(stack.times.front()), log_long = std::log(stack.times.back());
  const float full_weight = float(p * kMaxHatWeight);
  cv::Mat numerator(1, int(samples), CV_32F), denominator(1, int(samples), CV_32F);
  float* num = numerator.ptr<float>();
  float* den = denominator.ptr<float>();
  for (int y = row_begin; y < row_end; ++y) {
    std::fill(num, num + samples, 0.0f);
    std::fill(den, den + samples, 0.0f);
    for (int j = 0; j < p; ++j) {
      const std::uint8_t* z = stack.images[std::size_t(j)].ptr<std::uint8_t>(y);
      for (int c = 0; c < channels; ++c) {
        const float* table = tables.weighted_log[std::size_t(c * p + j)].data();
        for (std::size_t i = std::size_t(c); i < samples; i += std::size_t(channels)) {
          num[i] += table[z[i]];
          den[i] += tables.weight[z[i]];
        }
      }
    }
    float* valid = out.valid.ptr<float>(y);
    const std::uint8_t* shortest = stack.images.front().ptr<std::uint8_t>(y);
    const std::uint8_t* longest = stack.images.back().ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      float least = 1;
      for (int c = 0; c < channels; ++c) {
        const std::size_t i = std::size_t(x) * std::size_t(channels) + std::size_t(c);
        if (den[i] > 0) {
          num[i] /= den[i];
        } else {
          const Curve& g = response.g[std::size_t(c)];
          num[i] = float(2 * shortest[i] > kZmin + kZmax ? g[shortest[i]] - log_short : g[longest[i]] - log_long);
        }
        least = std::min(least, den[i] / full_weight);
      }
      valid[x] = least;
    }
    cv::Mat row(1, int(samples), CV_32F, out.radiance.ptr<float>(y));
    cv::exp(numerator, row);
    if (progress && (y - row_begin + 1) % 32 == 0)
      progress(static_cast<std::uint64_t>(y - row_begin + 1), static_cast<std::uint64_t>(row_end - row_begin));
  }
}

}  // namespace

MergeResult merge_debevec(const ExposureStack& stack, const Response& response, int threads,
                          const ProgressFn& progress) {
  validate_stack(stack);
  const cv::Mat& first = stack.images.front();
  const int channels = first.channels();
  if (response.channels() != channels)
    throw bad_input("the response has {} channels, the images {}", response.channels(), channels);
  const int p = int(stack.images.size());
  Tables tables;
  tables.weighted_log.resize(std::size_t(channels * p));
  for (int z = 0; z < kCodes; ++z) tables.weight[std::size_t(z)] = float(hat_weight(z));
  for (int c = 0; c < channels; ++c)
    for (int j = 0; j < p; ++j)
      for (int z = 0; z < kCodes; ++z)
        tables.weighted_log[std::size_t(c * p + j)][std::size_t(z)] =
            float(hat_weight(z) * (response.g[std::size_t(c)][std::size_t(z)] - std::log(stack.times[std::size_t(j)])));
  MergeResult out;
  out.radiance.create(first.rows, first.cols, CV_32FC(channels));
  out.valid.create(first.rows, first.cols, CV_32FC1);
  const int workers = std::max(1, std::min(threads, first.rows));
  std::vector<std::thread> pool;
  for (int k = 0; k < workers; ++k) {
    const int begin = int(std::int64_t(first.rows) * k / workers);
    const int end = int(std::int64_t(first.rows) * (k + 1) / workers);
    if (k + 1 == workers)
      merge_rows(stack, response, tables, begin, end, out, progress);
    else
      pool.emplace_back([&, begin, end] { merge_rows(stack, response, tables, begin, end, out); });
  }
  for (std::thread& t : pool) t.join();
  if (progress) progress(1, 1);
  return out;
}

}  // namespace fest::hdr

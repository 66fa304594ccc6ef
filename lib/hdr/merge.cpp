#include "hdr/merge.hpp"

#include <algorithm>
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

void merge_rows(const ExposureStack& stack, const Response& response, const Tables& tables, int row_begin,
                int row_end, MergeResult& out) {
  const int p = int(stack.images.size());
  const int channels = response.channels();
  const int width = stack.images.front().cols;
  const double log_short = std::log(stack.times.front()), log_long = std::log(stack.times.back());
  const float full_weight = float(p * kMaxHatWeight);
  std::vector<const std::uint8_t*> rows(std::size_t(p), nullptr);
  for (int y = row_begin; y < row_end; ++y) {
    for (int j = 0; j < p; ++j) rows[std::size_t(j)] = stack.images[std::size_t(j)].ptr<std::uint8_t>(y);
    float* radiance = out.radiance.ptr<float>(y);
    float* valid = out.valid.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      float least = 1;
      for (int c = 0; c < channels; ++c) {
        const std::size_t at = std::size_t(x) * std::size_t(channels) + std::size_t(c);
        float numerator = 0, denominator = 0;
        const std::array<float, kCodes>* table = &tables.weighted_log[std::size_t(c * p)];
        for (int j = 0; j < p; ++j) {
          const std::uint8_t z = rows[std::size_t(j)][at];
          numerator += table[j][z];
          denominator += tables.weight[z];
        }
        double log_e;
        if (denominator > 0) {
          log_e = numerator / denominator;
        } else {
          const std::uint8_t z_short = rows.front()[at];
          log_e = 2 * z_short > kZmin + kZmax ? response.g[std::size_t(c)][z_short] - log_short
                                              : response.g[std::size_t(c)][rows.back()[at]] - log_long;
        }
        radiance[at] = float(std::exp(log_e));
        least = std::min(least, denominator / full_weight);
      }
      valid[x] = least;
    }
  }
}

}  // namespace

MergeResult merge_debevec(const ExposureStack& stack, const Response& response, int threads) {
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
      merge_rows(stack, response, tables, begin, end, out);
    else
      pool.emplace_back([&, begin, end] { merge_rows(stack, response, tables, begin, end, out); });
  }
  for (std::thread& t : pool) t.join();
  return out;
}

}  // namespace fest::hdr

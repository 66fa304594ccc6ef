#include "hdr/debevec.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "core/error.hpp"

namespace fest::hdr {
namespace {

std::uint8_t value_at(const cv::Mat& image, int index, int channel) {
  return image.ptr<std::uint8_t>()[std::size_t(index) * std::size_t(image.channels()) + std::size_t(channel)];
}

}  // namespace

std::vector<int> pick_samples(const ExposureStack& stack, int channel, int samples) {
  const cv::Mat& first = stack.images.front();
  const int width = first.cols, height = first.rows;
  // A grid of about 16 N candidates: enough choice to cover the codes evenly, cheap to scan.
  const double cell = std::max(1.0, std::sqrt(double(width) * height / (16.0 * samples)));
  const std::size_t middle = stack.images.size() / 2;
  std::vector<std::pair<int, int>> candidates;  // (value in the middle exposure, index)
  for (double y = cell / 2; y < height; y += cell)
    for (double x = cell / 2; x < width; x += cell) {
      const int index = int(y) * width + int(x);
      double weight = 0;
      for (const cv::Mat& image : stack.images) weight += hat_weight(value_at(image, index, channel));
      if (weight > 0) candidates.emplace_back(value_at(stack.images[middle], index, channel), index);
    }
  std::sort(candidates.begin(), candidates.end());
  std::vector<int> picked;
  const std::size_t n = std::min<std::size_t>(std::size_t(samples), candidates.size());
  for (std::size_t k = 0; k < n; ++k) {
    // Evenly spaced ranks, both ends included: the darkest and brightest candidates.
    const std::size_t rank = n == 1 ? 0 : k * (candidates.size() - 1) / (n - 1);
    picked.push_back(candidates[rank].second);
  }
  return picked;
}

Response recover_response_debevec(const ExposureStack& stack, const DebevecOptions& options) {
  validate_stack(stack);
  if (options.samples < 1) throw usage_error("the number of sample pixels must be positive, got {}", options.samples);
  if (!(options.lambda >= 0 && std::isfinite(options.lambda)))
    throw usage_error("the smoothness weight lambda must be finite and not negative, got {}", options.lambda);
  const int p = int(stack.images.size());
  const double smooth = options.lambda;
  Response response;
  for (int c = 0; c < stack.images.front().channels(); ++c) {
    const std::vector<int> samples = pick_samples(stack, c, options.samples);
    const int n = int(samples.size());
    if (n * (p - 1) <= kZmax - kZmin)
      throw bad_input("too few usable sample pixels in channel {}: {} samples x {} exposures cannot determine "
                      "{} response values (N(P-1) must exceed {}); use more exposures or a larger image",
                      c + 1, n, p, kCodes, kZmax - kZmin);
    // Unknowns: g(0..255), then ln E_i. Rows: data terms, g(128) = 0, smoothness.
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> rhs;
    int row = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < p; ++j) {
        const int z = value_at(stack.images[std::size_t(j)], samples[std::size_t(i)], c);
        const double w = hat_weight(z);
        if (w == 0) continue;
        entries.emplace_back(row, z, w);
        entries.emplace_back(row, kCodes + i, -w);
        rhs.push_back(w * std::log(stack.times[std::size_t(j)]));
        ++row;
      }
    entries.emplace_back(row, (kZmin + kZmax + 1) / 2, 1.0);
    rhs.push_back(0);
    ++row;
    for (int z = kZmin + 1; z < kZmax; ++z) {
      const double w = smooth * hat_weight(z);
      entries.emplace_back(row, z - 1, w);
      entries.emplace_back(row, z, -2 * w);
      entries.emplace_back(row, z + 1, w);
      rhs.push_back(0);
      ++row;
    }
    Eigen::SparseMatrix<double> a(row, kCodes + n);
    a.setFromTriplets(entries.begin(), entries.end());
    a.makeCompressed();
    const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), Eigen::Index(rhs.size()));
    // Normal equations by sparse Cholesky: the ln E_i block of A^T A is diagonal, so the
    // fill-reducing ordering eliminates the samples first and the factor stays small
    // (SparseQR of the same system is ~100x slower). The weights span about 3 decades,
    // well within what squaring the condition number in double precision tolerates.
    const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(a.transpose() * a);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
      throw runtime_failure("response recovery: the least-squares system of channel {} is singular", c + 1);
    const Eigen::VectorXd x = solver.solve(a.transpose() * b);
    if (solver.info() != Eigen::Success || !x.allFinite())
      throw runtime_failure("response recovery: the least-squares solve of channel {} failed", c + 1);
    Curve g{};
    // Exactly zero at 128 (the solve leaves round-off there).
    const double offset = x[(kZmin + kZmax + 1) / 2];
    for (int z = 0; z < kCodes; ++z) g[std::size_t(z)] = x[z] - offset;
    response.g.push_back(g);
  }
  return response;
}

}  // namespace fest::hdr

#pragma once
// One-channel rows through a weight table eight outputs at a time (AVX2 gathers where the
// CPU has them): each lane sums its own output's taps in table order, with a separate
// multiply and add as the scalar loop does, so the values are bit-identical to
// pass_detail::filter_row_any. Outputs whose taps are not consecutive input indices
// (wrap edges) keep the scalar loop.

#include <cstdint>
#include <vector>

#include "sampling/weight_table.hpp"

namespace fest::sampling {

class GreyRowFilter {
 public:
  explicit GreyRowFilter(const WeightTable& t);
  void operator()(const float* src, float* dst) const;  // t.n_in values in, t.n_out out

 private:
  const WeightTable& t_;
  bool vector_ = false;                 // AVX2 present and at least one regular block
  std::vector<std::int32_t> start_;      // per output: first input index (8 per block)
  std::vector<std::int32_t> count_;      // per output: taps; -1 marks an irregular block
  std::vector<int> block_taps_;          // per block: most taps of its outputs
  std::vector<std::size_t> weight_at_;   // per block: first of its taps x 8 weights (tap-major)
  std::vector<float> weights_;
};

}  // namespace fest::sampling

#pragma once
// The inner loops of the separable passes (separable_pass.cpp), shared with the streamed
// resize (streamed_resize.cpp). Every output value is a sum over its taps in table order,
// without FMA, on every path: results are bit-identical whichever loop computes them.

#include <cstddef>

#include "sampling/weight_table.hpp"

namespace fest::sampling::pass_detail {

// One row of `c`-channel pixels through the table (t.n_in pixels in, t.n_out out).
void filter_row_any(const float* src, float* dst, const WeightTable& t, int c);

// Four rows at once, c = 3 or 4: each tap's index and weight fetched once for the four.
void filter_four_rows_any(const float* const* src, float* const* dst, const WeightTable& t, int c);

// dst[i] = Σ_j w[j] src[j][i] for i in [begin, end), in the taps' order.
void accumulate_rows(float* dst, const float* const* src, const float* w, std::size_t taps, std::size_t begin,
                     std::size_t end);

}  // namespace fest::sampling::pass_detail

#pragma once
// One axis of the separable resize (docs/resample.md "Separable passes and their order"). Rows are independent, so they are
// split across threads; each output value is summed in the same order whatever the
// thread count, which keeps the output bit-identical for any --threads.

#include "sampling/float_image.hpp"
#include "sampling/weight_table.hpp"

namespace fest::sampling {

// Resamples along x: table.n_in == in.width; the result is table.n_out wide.
FloatImage resample_rows(const FloatImage& in, const WeightTable& table, int threads);

// resample_rows on the stored pixels of `in`, each row decoded (to_working) on the fly:
// the first pass of a resize never holds a float copy of the whole input.
FloatImage resample_rows_decoded(const cv::Mat& in, const Encoding& enc, const WeightTable& table, int threads);

// Resamples along y: table.n_in == in.height; the result is table.n_out high.
FloatImage resample_columns(const FloatImage& in, const WeightTable& table, int threads);

}  // namespace fest::sampling

#pragma once
// The separable resize streamed through a ring of rows (docs/resample.md, "Streaming"):
// stored rows are read a band at a time, decoded (and, rows first, filtered along x) into
// a ring that holds only the rows the next outputs still read, and each group of output
// rows is summed along y from the ring. Neither the input nor the intermediate image is
// ever whole in memory. Every output value is the same sum, in the same order, as the
// two whole-image passes of separable_pass.hpp: the bytes do not change, whatever the
// thread count.

#include <optional>
#include <vector>

#include "sampling/float_image.hpp"
#include "sampling/stored_rows.hpp"
#include "sampling/weight_table.hpp"

namespace fest::sampling {

struct StreamedPasses {
  const WeightTable* x = nullptr;  // along x: n_in = the stored width
  const WeightTable* y = nullptr;  // along y: n_in = the stored height
  bool columns_first = true;       // y before x (the cheaper order for large reductions)
};

// Per-channel range of the decoded input (for ClampMode::range on float input).
struct ChannelRange {
  std::vector<float> lo, hi;
};

// The resize of `in` (decoded as `enc` says) through both tables, or nullopt when the
// first input row a group of outputs reads moves back (wrap edges, where the last
// outputs read the first rows again): the ring has dropped those rows, and the caller
// takes the whole-image passes. `range`, when given, receives
// the decoded input's per-channel min and max.
std::optional<FloatImage> resize_streamed(const StoredRows& in, const Encoding& enc, const StreamedPasses& passes,
                                          int threads, ChannelRange* range = nullptr);

}  // namespace fest::sampling

#pragma once
// Per-axis filter weights of the separable resize (docs/resample.md "Separable passes and their order"): for each output
// index, the input indices it reads (edge handling already applied) and their weights.

#include <vector>

#include "sampling/kernel.hpp"

namespace fest::sampling {

// How indices outside [0, n) are mapped back (docs/resample.md "Separable passes and their order").
enum class EdgeMode {
  clamp,    // repeat the edge sample
  reflect,  // mirror without repeating the edge sample: -1 -> 1, n -> n-2
  wrap,     // periodic
  zero,     // outside samples are 0: their weights are dropped, *not* renormalised
};

struct WeightTable {
  int n_in = 0, n_out = 0;
  // Taps of output o are index/weight[offset[o] .. offset[o+1]).
  std::vector<std::size_t> offset;
  std::vector<int> index;
  std::vector<float> weight;
};

// Output o is centred on u = (o + 0.5) n_in/n_out - 0.5 + shift (input index
// coordinates: pixel centres at half-integers, no half-pixel shift); the kernel is
// stretched by max(1, n_in/n_out) so that minification prefilters at the output rate.
// Kernels without a finite support are refused with a usage error.
WeightTable make_weight_table(int n_in, int n_out, const Kernel& k, double shift = 0,
                              EdgeMode edge = EdgeMode::clamp);

}  // namespace fest::sampling

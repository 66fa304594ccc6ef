#pragma once
// ClampMode::local of the resize (docs/resample.md "Separable passes and their order"): each output value is clamped to the
// [min, max] of the input samples under the kernel's main lobe, |n − u| ≤ σ along each
// axis (σ = max(1, n_in/n_out)), which removes ringing without flattening real contrast.

#include "sampling/float_image.hpp"

namespace fest::sampling {

// `in` is the working input, `out` the resized result (any size); shifts as in resize.
void clamp_to_local_range(const FloatImage& in, double shift_x, double shift_y, FloatImage& out);

}  // namespace fest::sampling

#pragma once
// Separable resize (spec resample.md §2.4): image in, image out, any kernel of the
// catalogue with finite support, in linear light with premultiplied alpha by default.

#include "core/image.hpp"
#include "sampling/kernel.hpp"
#include "sampling/weight_table.hpp"

namespace fest::sampling {

// Anti-ringing clamp (§2.4 step 7). The spec's fourth mode, `local`, is not offered yet.
enum class ClampMode {
  automatic,  // `range` for integer outputs (saturation does it), `none` for float
  none,       // keep negative lobes' overshoot
  range,      // clamp each channel to the input's min/max (working domain)
};

struct ResizeOptions {
  Kernel kernel = make_kernel("mitchell");  // the spec's default downscale kernel
  EdgeMode edge = EdgeMode::clamp;
  // true: sRGB images are decoded to linear light before filtering and encoded after
  // (the default); false filters the stored codes as plain numbers (--colorspace codes).
  bool linear_light = true;
  bool premultiply_alpha = true;  // false: --alpha none
  ClampMode clamp = ClampMode::automatic;
  double shift_x = 0, shift_y = 0;  // sub-pixel shift, in input pixels
  int threads = 0;                  // 0: every available core
};

// Resizes to width x height. The result has the input's depth, channel count and colour
// space. Sizes of 0, or of more than 2^31 output pixels, are usage errors; an empty or
// unsupported input is bad_input.
Image resize(const Image& in, int width, int height, const ResizeOptions& options = {});

}  // namespace fest::sampling

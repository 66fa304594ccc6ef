#pragma once
// Separable resize (docs/resample.md "Separable passes and their order"): image in, image out, any kernel of the
// catalogue -- finite kernels through weight tables, `sinc` through the line spectra,
// `dual:R` as correlation with R followed by the inverse of R's sampled autocorrelation --
// in linear light with premultiplied alpha by default.

#include <cstdint>
#include <optional>

#include "core/image.hpp"
#include "sampling/float_image.hpp"
#include "sampling/kernel.hpp"
#include "sampling/stored_rows.hpp"
#include "sampling/weight_table.hpp"

namespace fest::sampling {

// Anti-ringing clamp (docs/resample.md "Separable passes and their order").
enum class ClampMode {
  automatic,  // `range` for integer outputs (saturation does it), `none` for float
  none,       // keep negative lobes' overshoot
  range,      // clamp each channel to the input's min/max (working domain)
  local,      // clamp to the min/max of the input samples under the kernel's main lobe
};

struct ResizeOptions {
  Kernel kernel = make_kernel("mitchell");  // the default downscale kernel (resample(1))
  // A different kernel along y (the CRT display model: hold-box ⊗ spot along x, spot
  // along y); unset: `kernel` on both axes.
  std::optional<Kernel> kernel_y;
  EdgeMode edge = EdgeMode::clamp;
  // true: sRGB images are decoded to linear light before filtering and encoded after
  // (the default); false filters the stored codes as plain numbers (--colorspace codes).
  bool linear_light = true;
  bool premultiply_alpha = true;  // false: --alpha none
  ClampMode clamp = ClampMode::automatic;
  bool hicomp = false;              // highlight compression for HDR (docs/resample.md "Where each part is implemented")
  bool dither = false;              // triangular ±½ LSB noise before rounding
  std::uint64_t seed = 1;           // of the dither
  int output_depth = -1;            // CV_8U, CV_16U, CV_32F; -1: the input's
  double shift_x = 0, shift_y = 0;  // sub-pixel shift, in input pixels
  int threads = 0;                  // 0: every available core
  double dual_epsilon = 1e-3;       // regularisation 1/max(A_r, ε) of the spectral duals
};

// Resizes to width x height. The result has the input's channel count and colour space
// (and depth unless output_depth says otherwise). Sizes of 0, or of more than 2^31
// output pixels, are usage errors; an empty or unsupported input is bad_input.
Image resize(const Image& in, int width, int height, const ResizeOptions& options = {});

// The same from stored rows read a band at a time (a file streamed through the passes:
// docs/resample.md, "Streaming"); `color_space` is the stored image's. The common
// options stream both passes; hicomp, the local clamp, sinc, dual kernels, a separate y
// kernel and wrap edges read the whole image first.
Image resize(const StoredRows& in, ColorSpace color_space, int width, int height, const ResizeOptions& options = {});

// The filtering alone, on working values (linear, premultiplied as the caller decided).
// `integer_input`: ClampMode::range clamps to [0, 1]; `integer_output`: ClampMode::automatic
// acts as `range`.
FloatImage resize_working(const FloatImage& in, int width, int height, const ResizeOptions& options,
                          bool integer_input = false, bool integer_output = false);

// Highlight compression y = x (x ≤ 1), 1 + ln x (x > 1) and its inverse, on colour
// channels (alpha untouched).
void compress_highlights(FloatImage& img);
void expand_highlights(FloatImage& img);

}  // namespace fest::sampling

#pragma once
// Supersampled rendering of an analytic scene (docs/resample.md "Rendering analytic scenes"): each pixel is the normalised
// weighted sum Σ w(x_s − x_c) f(x_s) / Σ w of the samples within the pixel filter's reach,
// which may cover neighbouring pixels' samples when the filter is wider than a pixel.

#include <cstdint>

#include "sampling/float_image.hpp"
#include "sampling/kernel.hpp"
#include "sampling/sample_patterns.hpp"
#include "sampling/scenes.hpp"

namespace fest::sampling {

struct RenderOptions {
  int width = 0, height = 0;
  int samples = 16;  // per pixel
  Pattern pattern = Pattern::jitter;
  Kernel pixel_filter = make_kernel("box");
  double filter_scale = 1;  // the filter is k(d / filter_scale): --pixel-filter NAME:radius=R
  std::uint64_t seed = 1;
  int threads = 0;
};

// One channel, linear values. Analytic scenes (point) are evaluated at pixel centres.
FloatImage render(const Scene& scene, const RenderOptions& options);

}  // namespace fest::sampling

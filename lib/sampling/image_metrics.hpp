#pragma once
// Image error measures of `resample metrics` (docs/resample.md): RMSE / PSNR / max abs error
// against a reference, and the zone-plate aliasing energy (AE) and pass-band retention (PR).

#include <cstdint>
#include <vector>

#include "sampling/float_image.hpp"

namespace fest::sampling {

struct ErrorMeasures {
  double rmse = 0, psnr = 0, maxabs = 0;  // psnr with peak 1.0; +inf for identical images
  std::int64_t n_pixels = 0;              // pixels compared (inside the mask)
};

// Over every channel of the pixels whose mask value is non-zero (an empty mask: all).
// Images must have the same size and channel count (bad_input otherwise).
ErrorMeasures compare_images(const FloatImage& test, const FloatImage& ref, const std::vector<std::uint8_t>& mask = {});

struct Band {
  double lo = 0, hi = 0;  // local frequency range (lo, hi) in cycles per pixel
};

struct ZonePlateMeasures {
  double ae = 0;  // mean over the alias band of (I − ½)² / 0.125
  double pr = 0;  // pass band: mean (I − ½)² over mean (I_ideal − ½)²
  std::int64_t n_alias = 0, n_pass = 0;
};

// `img` is the zone plate of the given numax rendered at this size (its first channel,
// or the mean of the colour channels). Pixels are chosen by their centre's ν(r).
ZonePlateMeasures zoneplate_measures(const FloatImage& img, double numax, Band alias = {0.6, 1.0},
                                     Band pass = {0.0, 0.2});

// Horizontal power spectrum: the mean over rows (first channel, or the mean of R, G, B) of
// the one-sided periodogram of each row, normalised so that a cosine of amplitude A at a
// bin frequency contributes its mean square A²/2. Index k is frequency k / width cycles
// per pixel, k = 0 .. width/2.
std::vector<double> row_power_spectrum(const FloatImage& img);

}  // namespace fest::sampling

#pragma once
// Whole-line filters along one axis of a FloatImage (docs/resample.md "The 1-D chain and the optimal prefilter", "Separable passes and their order", "Kernels and their responses" sinc):
// the recursive B-spline-style inverse filters of the dual prefilters, their frequency-
// domain counterpart for other displays, and the ideal low-pass (DCT) resampler.

#include <functional>
#include <vector>

#include "sampling/float_image.hpp"

namespace fest::sampling {

enum class Axis { x, y };

// Applies the filter with z-transform Π_i λ_i / ((1 − z_i z⁻¹)(1 − z_i z)), λ_i =
// (1 − z_i)(1 − 1/z_i), along the axis: causal and anticausal first-order recursions per
// pole with mirror-boundary initialisation (Unser 1993). It inverts a symmetric FIR
// a[n] whose roots are the poles and whose sum is 1 (constants are kept).
void recursive_inverse(FloatImage& img, Axis axis, const std::vector<double>& poles, int threads);

// Multiplies the line spectra by gain(f), f in cycles per sample in [0, ½]: lines are
// extended by mirroring (half-sample symmetric, so no jump at the ends) and transformed
// as a DCT-II of their length.
void spectral_filter(FloatImage& img, Axis axis, const std::function<double(double)>& gain, int threads);

// Ideal low-pass resampling of every line to n_out samples: the line's DCT-II, truncated
// below min(n_in, n_out)/2 cycles per line (the output's Nyquist when shrinking), read
// back at the output's pixel centres (centre convention).
FloatImage spectral_resample(const FloatImage& img, Axis axis, int n_out, int threads);

}  // namespace fest::sampling

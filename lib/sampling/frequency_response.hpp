#pragma once
// Fourier transforms K(f) of catalogue kernels, normalised to K(0) = 1 (docs/resample.md:
// kernels integrate to 1), with f in cycles per pixel of the kernel's grid.

#include "sampling/kernel.hpp"

namespace fest::sampling {

// The closed form when the kernel has one, else numerical_response().
double frequency_response(const Kernel& k, double f);

// ∫k(x) cos(2πfx) dx / ∫k(x) dx by composite Simpson over [-radius, radius] with a step of
// at most `step` (docs/resample.md: 1e-4 px). Throws usage_error for kernels without a finite
// spatial form (sinc, dual:*) and for point sampling.
double numerical_response(const Kernel& k, double f, double step = 1e-4);

}  // namespace fest::sampling

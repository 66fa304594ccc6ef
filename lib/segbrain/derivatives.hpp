#pragma once
// Sampled Gaussian derivative kernels and separable convolution along one grid axis:
// the building blocks of the second-order operators (Laplacian of Gaussian for the
// Marr-Hildreth edges, the Hessian for tubularity). Kept apart from filters.cpp, whose
// plain Gaussian is tuned for speed; these favour exact moments over speed.

#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

// Kernel of the `order`-th derivative (0, 1 or 2) of a Gaussian of sigma_vox voxels,
// radius ceil(3 sigma) (at least 1), centred. Moments are made exact on the grid: order 0
// sums to 1; order 1 has zero sum and first moment -1 (so it differentiates a ramp
// exactly); order 2 has zero sum and second moment 2 (exact on a parabola), per voxel.
std::vector<double> gaussian_derivative_kernel(double sigma_vox, int order);

// Convolution of img along `axis` with a centred kernel, borders replicated; divided by
// spacing^scale_power along that axis (1 for first, 2 for second derivatives, so the
// result is per mm).
Image convolve_axis(const Grid& g, const Image& img, int axis, const std::vector<double>& kernel, int scale_power = 0);

// d^(o0+o1+o2) (G_sigma * I) / dR^o0 dA^o1 dS^o2 with sigma in mm; axes listed in
// `skip` (per entry true) are neither smoothed nor differentiated (in-plane filtering).
Image gaussian_derivative(const Grid& g, const Image& img, double sigma_mm, const int orders[3], const bool skip[3]);

}  // namespace fest::segbrain

#pragma once
// The filter that mip-mapping really applies (docs/resample.md "Mip-mapping", Fig. 10.12/10.13): the weights
// of the level-0 texels in one linearly interpolated lookup at level L. The pyramid is
// linear, so the weights are the lookup's interpolation vector pulled back through every
// reduction step (the transposed pyramid).

#include <string>
#include <vector>

namespace fest::sampling {

enum class MipBuild { box, gaussian };

MipBuild parse_mip_build(const std::string& name);  // "box" | "gaussian", else usage error

// Weights w_i of the level-0 texels i = 0 .. n0−1 for a lookup at position x (level-0
// texel units) at level `level` (fractional: trilinear blend of ⌊level⌋ and ⌈level⌉).
// The texture is periodic with n0 = 2^⌈level⌉ · blocks texels, so borders play no part;
// x is taken modulo n0. Σw = 1.
std::vector<double> mip_kernel_1d(double level, double x, MipBuild build, int blocks = 8);

}  // namespace fest::sampling

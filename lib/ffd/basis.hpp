#pragma once
// One-dimensional bases of a free-form deformation lattice along one axis with `count`
// control points over the local coordinate s in [0, 1] (docs/ffd.md section 2.2):
//  * bernstein: Sederberg & Parry 1986 eq. (2), w_i(s) = C(n, i) s^i (1 - s)^(n - i),
//    n = count - 1; global support;
//  * bspline: clamped uniform B-spline of degree min(3, count - 1) (Cox-de Boor), control
//    points at the Greville abscissae so that a zero displacement is the identity and
//    affine displacement fields are reproduced exactly; local support;
//  * linear: piecewise-linear hat functions on the uniform rest points;
//  * catmull_rom: the interpolating cubic of each cell, ghost points beyond the ends by
//    linear extrapolation (P_-1 = 2 P_0 - P_1), so linear fields are reproduced.

#include <array>

namespace fest::ffd {

enum class Basis { bernstein, bspline, linear, catmull_rom };

// Largest number of control points per axis (Blender's lattice limit).
inline constexpr int max_axis_points = 64;

const char* basis_name(Basis b) noexcept;
// Throws fest::Error(Status::usage) for an unknown name.
Basis basis_from_name(const char* name);

// Non-zero weights at s: w[k] and dw[k] = d w / d s belong to control point first + k,
// k < count_out.
struct AxisWeights {
  int first = 0;
  int count = 0;
  std::array<double, max_axis_points> w{};
  std::array<double, max_axis_points> dw{};
};

// s must lie in [0, 1]. The weights sum to 1 (partition of unity). Derivatives are
// filled only when asked (the deformation itself does not need them).
void axis_weights(Basis basis, int count, double s, AxisWeights& out, bool derivatives = true);

// Local coordinate of control point i at rest (uniform i/(count-1); Greville abscissa
// for bspline).
double rest_coordinate(Basis basis, int count, int i);

}  // namespace fest::ffd

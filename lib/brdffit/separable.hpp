#pragma once
// Separable BRDF approximation for display (docs/brdffit.md §6, `factor`; chapter 8
// §8.7.1 after Kautz & McCool 1999; reconstructed as a rank-1 factorisation of the sampled
// BRDF). A homogeneous BRDF is tabulated on a grid of two directions -- half and
// difference vectors (Rusinkiewicz' (theta_h, phi_h) x (theta_d, phi_d)), or, for
// comparison, the naive (omega_o, omega_i) -- as a matrix F (rows: first direction,
// columns: second) and approximated by g h^T, per colour channel.
//
// Half/difference pairs whose incoming or outgoing direction falls below the surface are
// not BRDF values; they get weight 0, and g, h minimise the weighted squared error by
// alternating least squares (g_i = sum_j w_ij F_ij h_j / sum_j w_ij h_j^2 and the same
// for h). With all weights 1 (the naive grid) this is the power iteration of the leading
// singular pair, i.e. the rank-1 SVD of docs/brdffit.md §6.
//
// Grids: directions at cell centres, theta in [0, pi/2) with theta_bins cells, phi in
// [0, 2 pi) with phi_bins cells; a direction's index is theta_index * phi_bins + phi_index.

#include <vector>

#include <Eigen/Core>

#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

enum class SeparableGrid { half_difference, out_in };

struct SeparableOptions {
  int theta_bins = 32, phi_bins = 64;
  int max_iterations = 100;
  double tolerance = 1e-9;  // stop when the relative change of the error is below this
  int threads = 1;
};

struct SeparableFactors {
  SeparableGrid grid = SeparableGrid::half_difference;
  int theta_bins = 0, phi_bins = 0;
  // Per direction of the grid (theta-major), RGB. h is scaled to mean 1 over the entries
  // with any weight; g carries the magnitude. Directions that never pair with a valid one
  // get 0.
  std::vector<Eigen::Vector3d> g, h;
  Eigen::Vector3d relative_rms = Eigen::Vector3d::Zero();  // per channel: ||W.(F - g h^T)|| / ||W.F||
  double relative_rms_all = 0;                              // over the three channels together
  int iterations = 0;
};

// The unit direction at the centre of grid cell (theta_index, phi_index).
Eigen::Vector3d grid_direction(int theta_index, int phi_index, const SeparableOptions& options);

// Incoming and outgoing directions of a half vector h and a difference vector d (d in the
// frame where h is the pole; Rusinkiewicz 1998): omega_i = R(h) d, omega_o its mirror
// about h. Both in the surface frame (z = normal).
void half_difference_to_in_out(const Eigen::Vector3d& half, const Eigen::Vector3d& difference, Eigen::Vector3d& in,
                               Eigen::Vector3d& out);

// Throws bad_input on grids outside 1..1024 cells per angle.
SeparableFactors factor_brdf(const reflectance::LafortuneBrdf& brdf, SeparableGrid grid, const SeparableOptions& options);

}  // namespace fest::brdffit

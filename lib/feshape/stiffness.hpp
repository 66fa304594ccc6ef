#pragma once
// The stiffness of the local displacements: the "thin plate under tension" energy of
// seed App. C eq. 7, discretized on linear triangles in the parameter domain
// (docs/feshape.md §1.3). One matrix acts on each coordinate of d independently.

#include <array>

#include <Eigen/SparseCore>

#include "feshape/triangulation.hpp"

namespace fest::feshape {

// Weights of eq. 7 in the seed's listing order: w00 (|d|^2), w01 (dv), w10 (du),
// w02 (dvv), w11 (duv), w20 (duu).
struct StiffnessWeights {
  double w00 = 0.5, w01 = 0.5, w10 = 0.5, w02 = 0, w11 = 0, w20 = 0;
};

// K = w00 M + w10 K_u + w01 K_v + w20 K_u M^-1 K_u + w02 K_v M^-1 K_v
//     + w11 K_uv^T M^-1 K_uv, with the lumped mass M_ii = sum of A_t/3 (parameter-space
// areas) and K_u, K_v, K_uv from the constant gradients of the barycentric shape
// functions; E(d) ~ 1/2 d^T K d per coordinate.
Eigen::SparseMatrix<double> assemble_stiffness(const Triangulation& t, const StiffnessWeights& w);

// The lumped mass alone (parameter-space area per node).
Eigen::VectorXd lumped_mass(const Triangulation& t);

}  // namespace fest::feshape

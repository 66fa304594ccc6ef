#pragma once
// The local degrees of freedom q_d (seed App. C §3-4): the equilibrium of
// D q_d' + K q_d = f_d for a fixed assignment, i.e. the minimiser of
// beta/2 sum |z - x(u_z)|^2 + 1/2 q_d^T K q_d (docs/feshape.md §1.4-1.5), one sparse
// solve per coordinate of the model frame.

#include <vector>

#include <Eigen/SparseCore>

#include "feshape/closest.hpp"
#include "feshape/model.hpp"

namespace fest::feshape {

// The residual of each point is taken along `normals[p]` (world frame; the direction
// from its closest mesh point to it, the face normal when it lies on the mesh): at the
// converged assignment the seed's force f = beta (z - x(u_z)) has exactly that
// direction, so the fixed point is the same and it is reached in far fewer iterations
// than with the full 3-vector residual (the tangential part only slides the points).
// Solves (beta A^T W A + K (x) I3) q_d = beta A^T W (y - S), A_pi = lambda_pi (eq. 11),
// W_p = n_p n_p^T, y = R^T(z - c), S = sum lambda_i s(u_i), K from eq. 7. Fails
// (Status::failure) when the system cannot be factored.
void solve_local_equilibrium(Model& m, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<MeshPoint>& assigned, const std::vector<Eigen::Vector3d>& normals,
                             const Eigen::SparseMatrix<double>& k, double beta);

}  // namespace fest::feshape

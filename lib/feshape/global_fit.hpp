#pragma once
// The global degrees of freedom q_c, q_theta, q_s (seed App. C eqs. 4-5): their Jacobian
// L = [I  B  RJ] and Levenberg-Marquardt steps that move them to the equilibrium of the
// first-order dynamics (eq. 6), where the generalized forces J^T f vanish
// (docs/feshape.md §1.5, "equilibrium" solver).

#include <vector>

#include <Eigen/Core>

#include "feshape/closest.hpp"
#include "feshape/model.hpp"

namespace fest::feshape {

constexpr int n_pose_global = 6 + n_global;  // c (3), rotation (3), q_s (11)
using GlobalStep = Eigen::Matrix<double, n_pose_global, 1>;

// c += dc, R <- exp([dtheta]x) R, q_s += dq_s (then clamped to the model's ranges).
void apply_global_step(Model& m, const GlobalStep& step);

// Moves (u, v) to the nearest point of the global (smooth) surface c + R s(u, v) to z
// by damped Gauss-Newton in the parameter domain; returns the squared distance.
double project_to_surface(const Model& m, const Eigen::Vector3d& z, Eigen::Vector2d& uv);

// One accepted Levenberg-Marquardt step on the smooth surface (level G): point-to-plane
// residuals of the projected data points. `uv` holds every point's projection (warm
// start, updated). Returns false when no step lowers the energy (converged);
// `energy` is sum |z - x(u_z)|^2.
bool global_step_smooth(Model& m, const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& uv,
                        double& mu, double& energy, int threads);

// Direction of each point's residual: from its closest mesh point to it, or the face's
// unit normal when the point lies on the mesh.
std::vector<Eigen::Vector3d> residual_directions(const std::vector<Eigen::Vector3d>& points,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const std::vector<std::array<int, 3>>& tris,
                                                 const std::vector<MeshPoint>& assigned);

// One accepted Levenberg-Marquardt step with the flat model and a fixed assignment
// (levels with local displacements): x(u_z) = sum lambda_i x_i, residuals along
// `normals` (point-to-plane). Returns false when no step lowers the energy.
bool global_step_flat(Model& m, const std::vector<Eigen::Vector3d>& points, const std::vector<MeshPoint>& assigned,
                      const std::vector<Eigen::Vector3d>& normals, double& mu, double& energy);

// Sum over points of (n_p . (z - sum lambda_i x_i))^2 for a fixed assignment.
double flat_energy(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& positions,
                   const std::vector<std::array<int, 3>>& tris, const std::vector<MeshPoint>& assigned,
                   const std::vector<Eigen::Vector3d>& normals);

}  // namespace fest::feshape

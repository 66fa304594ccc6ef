#pragma once
// The global shape of the deformable model (docs/feshape.md §2): a superquadric
// ellipsoid (seed App. C eq. 2, Barr 1981) with linear tapering along axes 1, 2 and
// bending along axis 3 (eq. 3), as a function of the material coordinates (u, v) and the
// 11 global parameters q_s = (a, a1, a2, a3, e1, e2, t1, t2, b1, b2, b3).
// Evaluated in double and in Eigen's forward-mode AutoDiffScalar (for J = ds/dq_s,
// eq. 4, and for ds/du, ds/dv in the projection of data points onto the surface).

#include <array>
#include <string>

#include <Eigen/Core>

namespace fest::feshape {

constexpr int n_global = 11;
using GlobalParams = std::array<double, n_global>;
enum GlobalIndex { ia = 0, ia1, ia2, ia3, ie1, ie2, it1, it2, ib1, ib2, ib3 };

// Names in the order of q_s ("a", "a1", ... "b3"), for reports and messages.
const std::array<const char*, n_global>& global_names();

// Why a parameter vector is outside the model's ranges (a > 0, 0 < a_i <= 1, e_i > 0,
// |t_i| <= 1, |b2| <= 1, 0 <= b3 <= 1, all finite); empty when it is valid.
std::string check_global(const GlobalParams& q);
// The same ranges enforced after an update step (e_i kept in [0.1, 4]; a_i in
// [1e-3, 1]; a >= 1e-9), as in docs/feshape.md §1.2. An a_i above 1 is first folded
// into a (a *= max a_i, a_i /= max a_i): the shape is unchanged.
void clamp_global(GlobalParams& q);

// s(u, v; q_s), eq. 2 + eq. 3, in the model frame.
Eigen::Vector3d shape(const GlobalParams& q, double u, double v);
// J = ds/dq_s (3 x 11) by forward-mode automatic differentiation; the |.|^e ln|.| terms
// at cos u = 0 or sin v = 0 are taken as 0 (docs/feshape.md §1.2).
Eigen::Matrix<double, 3, n_global> shape_jacobian(const GlobalParams& q, double u, double v);
// ds/du and ds/dv (columns), for projecting points onto the surface.
Eigen::Matrix<double, 3, 2> shape_tangents(const GlobalParams& q, double u, double v);

}  // namespace fest::feshape

#pragma once
// Exact joint preservation (seed section 16; docs/ffd.md 2.3, after Hsu, Hughes & Kaufman
// 1992 "Direct manipulation of free-form deformations"): the FFD is linear in the
// displacements, p'_c = p_c + W dP with W_ck = w_k(p_c); the smallest correction delta
// (least squares over the control points) that puts every joint on its target is
//     delta = W^T (W W^T + lambda I)^-1 (Y - P_c - W dP),
// one solve for x, y and z, lambda = 1e-12 trace(W W^T) / C, refined once on its residual.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ffd/lattice.hpp"

namespace fest::ffd {

struct Joint {
  std::string name;
  Eigen::Vector3d rest;    // position on the undeformed body
  Eigen::Vector3d target;  // where the deformed body must have it
};

struct JointSolve {
  double max_error_before = 0;  // |FFD(rest) - target| before the correction
  double max_error_after = 0;
  double correction_norm = 0;   // ||delta|| (Frobenius over control points)
  int rank = 0;                 // numerical rank of W
  bool exact = true;            // false: more independent joints than control points
};

// Corrects lattice.displacement in place. Control points whose indices are in `fixed`
// keep their displacement. Throws fest::Error(bad_input) for a joint outside the box
// (the lattice cannot move it).
JointSolve preserve_joints(Lattice& lattice, const std::vector<Joint>& joints, const std::vector<std::size_t>& fixed = {});

}  // namespace fest::ffd

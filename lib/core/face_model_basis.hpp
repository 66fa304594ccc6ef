#pragma once
// The face model's basis storage and the invariants every reader enforces
// (docs/facefit.md §1). Eigen in the signatures: include only where the basis is built.

#include <Eigen/Core>

#include "core/face_model.hpp"

namespace fest::face {

// Makes a model own a double basis (n×k column-major) given as a matrix.
void set_owned_basis(Model& model, const Eigen::MatrixXd& basis);
// The same, stored as float32 (what .mmb files normally hold).
void set_owned_basis_f32(Model& model, const Eigen::MatrixXd& basis);
// The basis as a double matrix (a copy; tests and model building).
Eigen::MatrixXd basis_matrix(const Model& model);

// Checks the invariants readers must enforce (docs/facefit.md §1): sizes consistent, mean and σ
// finite, σ > 0, columns unit length within 1e-3 (or renormalised when fix_basis). Throws
// bad_input naming the problem. σ not descending is repaired by reordering (that copies
// the basis into owned storage).
struct CheckResult {
  bool reordered = false;
  bool renormalised = false;
};
CheckResult check_model(Model& model, bool fix_basis);

}  // namespace fest::face

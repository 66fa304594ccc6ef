#pragma once
// The morphable model's algebra (docs/facefit.md §1): reconstruction, projection onto the
// basis, truncation. The model itself is core/face_model.hpp.

#include <cstddef>

#include <Eigen/Core>

#include "core/face_model.hpp"
#include "core/face_model_basis.hpp"

namespace fest::facefit {

// The model type, its basis storage and its invariant check are plain data shared with
// formats/facemodel (core/face_model.hpp); facefit names them as its own.
using face::CheckResult;
using face::Dtype;
using face::Model;
using face::basis_matrix;
using face::check_model;
using face::set_owned_basis;
using face::set_owned_basis_f32;

// v = v̄ + S diag(σ) c for the first c.size() components (the rest are 0).
Eigen::VectorXd reconstruct(const Model& model, const Eigen::VectorXd& c);
// The same shape as float32 into out (n() floats, the caller's buffer): what binary PLY
// output stores, without a double copy of the mesh per fit. For a float32 basis the
// values equal float(reconstruct(model, c)) exactly (same GEMV, mean added in double).
void reconstruct_f32(const Model& model, const Eigen::VectorXd& c, float* out);

// S^T (v - v̄) / σ: the standardised coefficients of a complete shape (exact for shapes
// inside the span when S is orthonormal).
Eigen::VectorXd coefficients_of(const Model& model, const Eigen::VectorXd& shape);

// Keeps the first k components (k ≤ components). The basis pointer is shared.
Model truncated(const Model& model, std::size_t k);

}  // namespace fest::facefit

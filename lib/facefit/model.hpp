#pragma once
// The morphable model in memory (docs/facefit.md §1): mean v̄ ∈ R^n, orthonormal basis
// S = (s_1 .. s_k) ∈ R^{n×k} (column-major, column i is s_i), standard deviations σ_i
// (descending), optional triangles, landmark map and evaluation mask.
//
// The basis is the one large array (91 MB in float32 for the paper's 75 972 vertices
// and 99 components); it is held through a pointer so that a memory-mapped file can back
// it without a copy. `storage` keeps whatever owns those bytes alive (an mmap, a vector).

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fest::facefit {

enum class Dtype { f32, f64 };

struct Model {
  int dims = 3;                      // 3 for faces; 2 allowed (generic estimator)
  std::size_t points = 0;            // p
  std::size_t components = 0;        // k
  std::vector<double> mean;          // n = dims * points, interleaved x y z per point
  std::vector<double> sigma;         // k standard deviations, descending
  Dtype basis_type = Dtype::f32;
  const void* basis = nullptr;       // n×k column-major, float or double per basis_type
  std::shared_ptr<const void> storage;  // owner of the basis bytes
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::map<std::string, std::uint32_t> landmarks;  // landmark name -> vertex index
  std::vector<std::uint32_t> eval_mask;            // vertices evaluated by E_full (empty = all)
  std::string units = "mm";
  std::string source;
  std::string license;
  std::size_t training_examples = 0;  // m

  std::size_t n() const noexcept { return static_cast<std::size_t>(dims) * points; }
  double basis_at(std::size_t row, std::size_t col) const noexcept {
    const std::size_t i = col * n() + row;
    return basis_type == Dtype::f32 ? static_cast<const float*>(basis)[i]
                                    : static_cast<const double*>(basis)[i];
  }
};

// Makes a model own a double basis (n×k column-major) given as a matrix.
void set_owned_basis(Model& model, const Eigen::MatrixXd& basis);
// The same, stored as float32 (what .mmb files normally hold).
void set_owned_basis_f32(Model& model, const Eigen::MatrixXd& basis);
// The basis as a double matrix (a copy; tests and model building).
Eigen::MatrixXd basis_matrix(const Model& model);

// Checks the invariants readers must enforce (docs/facefit.md §1): sizes consistent, mean and σ
// finite, σ > 0, columns unit length within 1e-3. Throws bad_input naming the problem.
// σ not descending is repaired by reordering (that copies the basis into owned storage).
struct CheckResult {
  bool reordered = false;
  bool renormalised = false;
};
CheckResult check_model(Model& model, bool fix_basis);

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

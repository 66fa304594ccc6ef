#pragma once
// The morphable face model and its landmark types, as plain data: what formats/facemodel
// reads and writes and lib/facefit computes with (docs/facefit.md §1). Mean v̄ ∈ R^n,
// orthonormal basis S = (s_1 .. s_k) ∈ R^{n×k} (column-major, column i is s_i), standard
// deviations σ_i (descending), optional triangles, landmark map and evaluation mask.
//
// The basis is the one large array (91 MB in float32 for the paper's 75 972 vertices
// and 99 components); it is held through a pointer so that a memory-mapped file can back
// it without a copy. `storage` keeps whatever owns those bytes alive (an mmap, a vector).
// The basis helpers and the invariant check are in core/face_model_basis.hpp.

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fest::face {

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

// A landmark observation as read from a file, before it is tied to a model vertex: it
// names a landmark id (looked up in a landmark-to-vertex map) or a vertex index.
struct LandmarkEntry {
  std::string id;             // landmark name ("37", "nose_tip"); empty when given by vertex
  bool by_vertex = false;
  std::uint32_t vertex = 0;
  double u = 0, v = 0;        // px
  double sigma = 0;           // px, 0 = not given
  std::size_t line = 0;       // source line, for messages
};

using LandmarkMap = std::map<std::string, std::uint32_t>;

// A named vertex of a vertex set (landmark sets, feature sets).
struct NamedVertex {
  std::string name;
  std::uint32_t vertex = 0;
};

}  // namespace fest::face

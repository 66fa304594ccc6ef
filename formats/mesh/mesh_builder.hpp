#pragma once
// Helpers shared by the mesh readers and writers: adding faces to an OpenMesh mesh
// while counting the ones its halfedge structure cannot hold, the "fest:skipped_faces"
// mesh property, exact number formatting, colour scaling and output compaction.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh.hpp"

namespace fest::formats::mesh_detail {

// Makes OpenMesh's omerr()/omlog()/omout() streams quiet (add_face reports "complex
// edge" there): library code must not print. Idempotent, thread-safe.
void silence_openmesh();

// Adds faces in file order. A vertex index outside [0, n_vertices) is malformed input
// and throws; a face OpenMesh's connectivity cannot hold (fewer than three vertices,
// a vertex repeated, a complex edge or non-manifold vertex) is skipped and counted,
// so it never vanishes without a trace (finish() stores the count on the mesh).
class MeshBuilder {
 public:
  MeshBuilder(Mesh& mesh, const char* format_label) : mesh_(mesh), label_(format_label) {}

  // `face_number` is 1-based, for the message.
  Mesh::FaceHandle add_face(const std::uint32_t* indices, std::size_t count, std::size_t face_number);
  std::size_t skipped() const { return skipped_; }
  // Stores the count of skipped faces as the mesh property (only when non-zero).
  void finish();

 private:
  Mesh& mesh_;
  const char* label_;
  std::vector<Mesh::VertexHandle> handles_;
  std::vector<std::uint32_t> sorted_;
  std::size_t skipped_ = 0;
  std::vector<std::vector<int>> skipped_list_;  // their vertex indices, for skipped_face_list()
};

void set_skipped_faces_property(Mesh& mesh, std::size_t count);

// Shortest text that reads back as exactly the same value ("0.1", "-0", "1e-300").
void append_number(std::string& out, double value);
void append_number(std::string& out, float value);

// True when every value converts to float and back unchanged (NaN counts as exact:
// a float NaN is still NaN), so a binary writer may store floats without rounding.
bool exactly_float(const double* values, std::size_t count);
bool points_are_floats(const Mesh& mesh);
bool normals_are_floats(const Mesh& mesh);

// double -> float without undefined behaviour: out-of-range values become +-infinity
// (what rounding would give), NaN stays NaN.
float narrow_to_float(double value);

// Colour components: floats in [0,1] and integers in [0,255] to a byte.
std::uint8_t color_from_unit(double value);
std::uint8_t color_from_byte_range(double value);

// Writers number vertices 0..n-1 by handle index; a mesh with deleted (not yet
// garbage-collected) elements is copied and compacted first. Returns the mesh to write.
const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage);

// Largest vertex/face count a reader accepts: OpenMesh handles are int.
constexpr std::uint64_t max_element_count = 0x7fffffffu - 1;

}  // namespace fest::formats::mesh_detail

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
#include "formats/mesh/mesh_io.hpp"

namespace fest::formats::mesh_detail {

// Makes OpenMesh's omerr()/omlog()/omout() streams quiet (add_face reports "complex
// edge" there): library code must not print. Idempotent, thread-safe.
void silence_openmesh();

// Adds faces in file order. A vertex index outside [0, n_vertices) is malformed input
// and throws; a face OpenMesh's connectivity cannot hold (fewer than three vertices,
// a vertex repeated, a complex edge or non-manifold vertex) is kept beside the mesh
// with its place in the file's face order and its colour, so it never vanishes
// (finish() stores them on the mesh).
class MeshBuilder {
 public:
  MeshBuilder(Mesh& mesh, const char* format_label) : mesh_(mesh), label_(format_label) {}

  // `face_number` is 1-based: the face's place in the file, and for the message.
  // `color` (may be null) is kept for a skipped face; white when null.
  Mesh::FaceHandle add_face(const std::uint32_t* indices, std::size_t count, std::size_t face_number,
                            const Mesh::Color* color = nullptr);
  std::size_t skipped() const { return skipped_; }
  // Stores the skipped faces (count, list, places, colours) as mesh properties.
  void finish();

 private:
  Mesh& mesh_;
  const char* label_;
  std::vector<Mesh::VertexHandle> handles_;
  std::vector<std::uint32_t> sorted_;
  std::size_t skipped_ = 0;
  std::vector<std::vector<int>> skipped_list_;  // their vertex indices, for skipped_face_list()
  std::vector<std::size_t> skipped_places_;     // 0-based place among the file's faces
  std::vector<Mesh::Color> skipped_colors_;
};

// Faces kept beside the halfedge mesh, as a writer sees them: vertex indices, the
// place of each among the written faces (empty: after the mesh's own faces) and
// colours (empty: white).
struct FacesBeside {
  std::vector<std::vector<int>> faces;
  std::vector<std::size_t> places;
  std::vector<Mesh::Color> colors;
};
FacesBeside extra_faces_to_write(const Mesh& mesh);

// Calls visit(const std::vector<int>& vertices, const Mesh::Color* face_color,
// Mesh::FaceHandle face) for every face a writer writes, in order: the mesh's own faces
// with `beside` at their places. face_color is null when the mesh has no face colours;
// `face` is invalid for a face from `beside`.
template <class Visit>
void for_each_written_face(const Mesh& mesh, const FacesBeside& beside, Visit&& visit) {
  std::vector<int> vertices;
  const bool colors = mesh.has_face_colors();
  const Mesh::Color white(255, 255, 255);
  std::size_t next = 0, written = 0;
  auto flush_beside = [&](bool all) {
    while (next < beside.faces.size() &&
           (all || (next < beside.places.size() && beside.places[next] <= written))) {
      const Mesh::Color* c = colors ? (next < beside.colors.size() ? &beside.colors[next] : &white) : nullptr;
      visit(beside.faces[next], c, Mesh::FaceHandle());
      ++next;
      ++written;
    }
  };
  for (auto f : mesh.faces()) {
    if (!beside.places.empty()) flush_beside(false);
    vertices.clear();
    for (auto v : mesh.fv_range(f)) vertices.push_back(v.idx());
    visit(vertices, colors ? &mesh.color(f) : nullptr, f);
    ++written;
  }
  flush_beside(true);
}

// How the input stored positions or normals, recorded by the readers for
// CoordinatePrecision::automatic (mesh_io.hpp).
enum class CoordinateStorage : int {
  unknown = 0,   // no reader: float when every value is exactly a float
  binary = 1,    // binary numbers (double, int32 ...): float when every value is exactly a float
  float32 = 2,   // declared float32 (or a smaller integer type): float when every value's
                 // text reads back from its float (binary floats always do; a tool's
                 // computed values mostly do not, and stay double)
  decimal = 3,   // decimal text: float when every value's text reads back from its float
};
void set_point_storage(Mesh& mesh, CoordinateStorage storage);
void set_normal_storage(Mesh& mesh, CoordinateStorage storage);
// What the text formats (OBJ, OFF) read: positions and normals written as decimals.
inline void set_decimal_storage(Mesh& mesh) {
  set_point_storage(mesh, CoordinateStorage::decimal);
  set_normal_storage(mesh, CoordinateStorage::decimal);
}
// Whether a binary writer stores positions (normals) as float under `precision`.
bool write_points_as_float(const Mesh& mesh, CoordinatePrecision precision);
bool write_normals_as_float(const Mesh& mesh, CoordinatePrecision precision);
// True when the value's shortest float32 text reads back as the same double: the text a
// decimal file held for it fits a float (values that are exactly floats included).
bool decimal_fits_float(double value);

// What a reader read and did not keep (unread_parts()).
void set_unread_parts(Mesh& mesh, std::vector<MeshPart> parts);

// A reader's lenient-reading message (read_warnings()).
void add_read_warning(Mesh& mesh, std::string message);

void set_skipped_faces_property(Mesh& mesh, std::size_t count);

// Shortest text that reads back as exactly the same value ("0.1", "-0", "1e-300").
void append_number(std::string& out, double value);
void append_number(std::string& out, float value);
// Coordinates first..n-1 of v, each after a space (" x y z"), as append_number writes them.
template <class Vector>
void append_coordinates(std::string& out, const Vector& v, int n, int first = 0) {
  for (int k = first; k < n; ++k) {
    out.push_back(' ');
    append_number(out, v[k]);
  }
}

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

// What every text and binary writer starts from: the mesh compacted, and which
// per-vertex attributes it has. Not copyable: `mesh` may refer to its own storage.
class MeshToWrite {
 private:
  std::optional<Mesh> storage_;  // before `mesh`, which it may hold

 public:
  explicit MeshToWrite(const Mesh& input)
      : mesh(compacted(input, storage_)),
        normals(mesh.has_vertex_normals()),
        colors(mesh.has_vertex_colors()),
        texcoords(mesh.has_vertex_texcoords2D()) {}
  MeshToWrite(const MeshToWrite&) = delete;
  MeshToWrite& operator=(const MeshToWrite&) = delete;

  const Mesh& mesh;
  const bool normals, colors, texcoords;
};

// Largest vertex/face count a reader accepts: OpenMesh handles are int.
constexpr std::uint64_t max_element_count = 0x7fffffffu - 1;

}  // namespace fest::formats::mesh_detail

#pragma once
// Binary little-endian PLY with named per-vertex and per-face scalar properties beyond
// what fest::Mesh carries (radiosity writes float rad_r/rad_g/rad_b and irr_* per vertex,
// object_id and level per face). Columns are written in the order given, with the type
// each names; the file opens in every PLY reader (unknown properties are skipped there,
// and read_mesh keeps positions, normals and red/green/blue).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats {

struct PlyColumn {
  std::string name;
  std::string type;  // "float", "double", "uchar", "int"
  std::vector<double> values;
};

struct AttributedPly {
  std::vector<std::string> comments;                   // one header line each ("comment ...")
  std::vector<PlyColumn> vertex;                       // must include x, y, z
  std::vector<std::vector<std::uint32_t>> faces;       // vertex indices
  std::vector<PlyColumn> face;                         // one value per face each
};

// Throws bad_input for columns of unequal length, an unknown type, a face naming a
// vertex that does not exist, or a comment containing a line break.
std::string write_attributed_ply(const AttributedPly& ply);

// Reads any PLY (ascii, binary little or big endian) into the same form: every scalar
// property of the vertex and face elements as a column (type as the file names it, in
// its canonical spelling), the face's vertex_indices (or vertex_index) list as faces,
// comments. Other elements are read and skipped; list properties other than the face
// indices are refused (bad_input) rather than dropped. Counts are checked against the
// bytes before anything is allocated.
AttributedPly read_attributed_ply(std::string_view bytes);

}  // namespace fest::formats

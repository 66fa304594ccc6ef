// PLY writer: ascii, or binary little endian. Positions and normals are declared
// `float` unless float32 would lose precision the input had (write_points_as_float,
// CoordinatePrecision in mesh_io.hpp), else `double`; ascii output writes shortest
// round-trip numbers of what is stored. Faces kept beside the halfedge mesh are written
// in their place; line elements go into an `edge` element (vertex1 vertex2).

#include <cstring>

#include <fmt/format.h>

#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"

namespace fest::formats::mesh_detail {
namespace {

bool host_is_little_endian() {
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

template <typename T>
void put_le(std::string& out, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (!host_is_little_endian())
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

// A value that is float or double on output, as the header declared. Ascii text of a
// value declared float is its own shortest text when that reads back from the float
// (what the input's text was), else the float's value (--precision float rounding).
void put_real(std::string& out, double value, bool as_float, bool ascii) {
  if (ascii) append_number(out, as_float && !decimal_fits_float(value) ? static_cast<double>(narrow_to_float(value)) : value);
  else if (as_float) put_le(out, narrow_to_float(value));
  else put_le(out, value);
}

}  // namespace

std::string write_ply(const Mesh& input, bool ascii, CoordinatePrecision precision) {
  const MeshToWrite written(input);
  const Mesh& mesh = written.mesh;
  const bool normals = written.normals, colors = written.colors, texcoords = written.texcoords;
  const bool face_colors = mesh.has_face_colors();
  // Ascii text is exact either way; the declared type then only tells readers what
  // precision to expect.
  const bool float_points = write_points_as_float(mesh, precision);
  const bool float_normals = write_normals_as_float(mesh, precision);
  const FacesBeside extra = extra_faces_to_write(mesh);
  std::size_t max_valence = 0;
  for (auto f : mesh.faces()) max_valence = std::max<std::size_t>(max_valence, mesh.valence(f));
  for (const auto& f : extra.faces) max_valence = std::max(max_valence, f.size());
  // Line elements as edges: a polyline of n vertices is n - 1 edges.
  std::vector<std::pair<int, int>> edges;
  for (const auto& line : line_elements(mesh))
    for (std::size_t k = 0; k + 1 < line.size(); ++k) edges.emplace_back(line[k], line[k + 1]);
  const std::size_t n_faces = mesh.n_faces() + extra.faces.size();
  const bool small_lists = max_valence <= 255;

  std::string out = "ply\n";
  out += ascii ? "format ascii 1.0\n" : "format binary_little_endian 1.0\n";
  out += "comment written by fest\n";
  fmt::format_to(std::back_inserter(out), "element vertex {}\n", mesh.n_vertices());
  const char* point_type = float_points ? "float" : "double";
  fmt::format_to(std::back_inserter(out), "property {0} x\nproperty {0} y\nproperty {0} z\n", point_type);
  if (normals)
    fmt::format_to(std::back_inserter(out), "property {0} nx\nproperty {0} ny\nproperty {0} nz\n",
                   float_normals ? "float" : "double");
  if (colors) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (texcoords) out += "property float s\nproperty float t\n";
  fmt::format_to(std::back_inserter(out), "element face {}\n", n_faces);
  out += small_lists ? "property list uchar int vertex_indices\n" : "property list int int vertex_indices\n";
  if (face_colors) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (!edges.empty())
    fmt::format_to(std::back_inserter(out), "element edge {}\nproperty int vertex1\nproperty int vertex2\n", edges.size());
  out += "end_header\n";
  if (!ascii) {
    // Binary records have known sizes (faces taken as triangles): one allocation instead
    // of the string doubling through a large mesh's hundreds of megabytes.
    const std::size_t point = float_points ? 4 : 8, normal = float_normals ? 4 : 8;
    const std::size_t per_vertex = 3 * point + (normals ? 3 * normal : 0) + (colors ? 3 : 0) + (texcoords ? 8 : 0);
    const std::size_t per_face = (small_lists ? 1 : 4) + 3 * 4 + (face_colors ? 3 : 0);
    out.reserve(out.size() + mesh.n_vertices() * per_vertex + n_faces * per_face + edges.size() * 8);
  }

  auto put_color = [&](const Mesh::Color& c) {
    for (int k = 0; k < 3; ++k) {
      if (ascii) fmt::format_to(std::back_inserter(out), " {}", static_cast<unsigned>(c[k]));
      else out.push_back(static_cast<char>(c[k]));
    }
  };
  for (auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    for (int k = 0; k < 3; ++k) {
      if (ascii && k > 0) out.push_back(' ');
      put_real(out, p[k], float_points, ascii);
    }
    if (normals) {
      const Mesh::Normal& n = mesh.normal(v);
      for (int k = 0; k < 3; ++k) {
        if (ascii) out.push_back(' ');
        put_real(out, n[k], float_normals, ascii);
      }
    }
    if (colors) put_color(mesh.color(v));
    if (texcoords) {
      const Mesh::TexCoord2D& t = mesh.texcoord2D(v);
      for (int k = 0; k < 2; ++k) {
        if (ascii) {
          out.push_back(' ');
          append_number(out, t[k]);
        } else {
          put_le(out, t[k]);
        }
      }
    }
    if (ascii) out.push_back('\n');
  }
  for_each_written_face(mesh, extra, [&](const std::vector<int>& face, const Mesh::Color* color, Mesh::FaceHandle) {
    if (ascii) fmt::format_to(std::back_inserter(out), "{}", face.size());
    else if (small_lists) out.push_back(static_cast<char>(face.size()));
    else put_le(out, static_cast<std::int32_t>(face.size()));
    for (int v : face) {
      if (ascii) fmt::format_to(std::back_inserter(out), " {}", v);
      else put_le(out, static_cast<std::int32_t>(v));
    }
    if (color) put_color(*color);
    if (ascii) out.push_back('\n');
  });
  for (const auto& [a, b] : edges) {
    if (ascii) {
      fmt::format_to(std::back_inserter(out), "{} {}\n", a, b);
    } else {
      put_le(out, static_cast<std::int32_t>(a));
      put_le(out, static_cast<std::int32_t>(b));
    }
  }
  return out;
}

}  // namespace fest::formats::mesh_detail

// PLY reader: ascii, binary little endian and binary big endian. The header is
// parsed and size-checked by ply_header.cpp; this walks the body element by element.
// Known properties: vertex x y z, nx ny nz, red green blue, s t / u v / texture_u
// texture_v / texture_s texture_t; face vertex_indices (or vertex_index), red green
// blue; edge vertex1 vertex2 (line elements). Everything else (other properties, other
// elements) is read and skipped.

#include <type_traits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"
#include "formats/mesh/ply_body.hpp"
#include "formats/mesh/ply_header.hpp"

namespace fest::formats::mesh_detail {
namespace {

enum class Role { skip, x, y, z, nx, ny, nz, red, green, blue, u, v, indices };

Role vertex_role(const std::string& name) {
  struct Entry { const char* name; Role role; };
  static const Entry entries[] = {
      {"x", Role::x},          {"y", Role::y},          {"z", Role::z},
      {"nx", Role::nx},        {"ny", Role::ny},        {"nz", Role::nz},
      {"red", Role::red},      {"green", Role::green},  {"blue", Role::blue},
      {"diffuse_red", Role::red}, {"diffuse_green", Role::green}, {"diffuse_blue", Role::blue},
      {"s", Role::u},          {"t", Role::v},          {"u", Role::u},
      {"v", Role::v},          {"texture_u", Role::u},  {"texture_v", Role::v},
      {"texture_s", Role::u},  {"texture_t", Role::v},
  };
  const Entry* e = find_named(entries, name);
  return e ? e->role : Role::skip;
}

Role face_role(const std::string& name) {
  if (name == "vertex_indices" || name == "vertex_index") return Role::indices;
  if (name == "red") return Role::red;
  if (name == "green") return Role::green;
  if (name == "blue") return Role::blue;
  return Role::skip;
}

struct Layout {
  std::vector<Role> roles;
  bool has(Role r) const {
    for (Role role : roles)
      if (role == r) return true;
    return false;
  }
};

Layout vertex_layout(const PlyElement& e) {
  Layout layout;
  for (const PlyProperty& p : e.properties) {
    Role role = vertex_role(p.name);
    if (role != Role::skip && p.is_list)
      throw bad_input("PLY header: vertex property {} is a list, expected a scalar", fest::quoted_bytes(p.name));
    layout.roles.push_back(role);
  }
  if (e.count > 0 && !(layout.has(Role::x) && layout.has(Role::y) && layout.has(Role::z)))
    throw bad_input("PLY header: vertex element lacks an x, y or z property");
  return layout;
}

Layout face_layout(const PlyElement& e) {
  Layout layout;
  for (const PlyProperty& p : e.properties) {
    Role role = face_role(p.name);
    if (role == Role::indices && (!p.is_list || !ply_type_is_integer(p.type)))
      throw bad_input("PLY header: face property {} must be a list of integers", fest::quoted_bytes(p.name));
    if (role != Role::skip && role != Role::indices && p.is_list)
      throw bad_input("PLY header: face property {} is a list, expected a scalar", fest::quoted_bytes(p.name));
    layout.roles.push_back(role);
  }
  if (e.count > 0 && !layout.has(Role::indices)) throw bad_input("PLY header: face element has no vertex_indices list");
  return layout;
}

std::uint8_t to_color(double value, PlyType type) {
  return ply_type_is_integer(type) ? color_from_byte_range(value) : color_from_unit(value);
}

// Where the scalar integer properties vertex1 and vertex2 of an edge element are;
// false when it lacks them (then the element is not read as lines).
bool edge_ends(const PlyElement& e, std::size_t* ends) {
  std::size_t found[2] = {e.properties.size(), e.properties.size()};
  for (std::size_t k = 0; k < e.properties.size(); ++k) {
    const PlyProperty& p = e.properties[k];
    if (p.is_list || !ply_type_is_integer(p.type)) continue;
    if (p.name == "vertex1") found[0] = k;
    if (p.name == "vertex2") found[1] = k;
  }
  if (ends) ends[0] = found[0], ends[1] = found[1];
  return found[0] < e.properties.size() && found[1] < e.properties.size();
}

struct Faces {
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets{0};
  std::vector<Mesh::Color> colors;
};

template <class Source>
class BodyReader {
 public:
  BodyReader(Source& source, const PlyHeader& header, Mesh& mesh)
      : source_(source), header_(header), mesh_(mesh) {}

  void read_all(Faces& faces) {
    for (const PlyElement& e : header_.elements) {
      if (e.properties.empty()) continue;  // nothing stored per instance
      if (e.name == "vertex") read_vertices(e);
      else if (e.name == "face") read_faces(e, faces);
      else if (e.name == "edge" && edge_ends(e, nullptr)) read_edges(e);
      else skip_element(e);
    }
    if (std::size_t extra = source_.trailing(); extra != 0)
      throw bad_input("PLY: {} bytes of unexpected data after the last element", extra);
  }

  std::uint64_t vertex_count() const {
    for (const PlyElement& e : header_.elements)
      if (e.name == "vertex") return e.count;
    return 0;
  }

 private:
  [[noreturn]] void truncated(const PlyElement& e, std::uint64_t i) {
    throw bad_input("PLY body: {} {} of {} is truncated or not a valid number", fest::quoted_bytes(e.name), i + 1, e.count);
  }

  double value(const PlyElement& e, std::uint64_t i, PlyType type) {
    double v;
    if (!source_.read(type, v)) truncated(e, i);
    return v;
  }

  std::uint64_t list_length(const PlyElement& e, std::uint64_t i, const PlyProperty& p) {
    double n = value(e, i, p.count_type);
    // `n` is an integer (checked by the source); bound it before converting.
    if (!(n >= 0) || n > 4294967295.0 || !source_.can_hold(static_cast<std::uint64_t>(n), p.type))
      throw bad_input("PLY body: {} {} has a {} list of length {}, more than the file holds", fest::quoted_bytes(e.name), i + 1, fest::quoted_bytes(p.name), n);
    return static_cast<std::uint64_t>(n);
  }

  void skip_list(const PlyElement& e, std::uint64_t i, const PlyProperty& p) {
    std::uint64_t n = list_length(e, i, p);
    for (std::uint64_t k = 0; k < n; ++k) value(e, i, p.type);
  }

  // How the file stores a vector property (CoordinateStorage): declared float (or a
  // type every value of which is a float) is float; else text is decimal, binary binary.
  CoordinateStorage storage_of(const PlyElement& e, const Layout& layout, Role a, Role b, Role c) const {
    bool fits_float = true;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      if (layout.roles[k] != a && layout.roles[k] != b && layout.roles[k] != c) continue;
      const PlyType t = e.properties[k].type;
      fits_float = fits_float && (t == PlyType::float32 || ply_type_size(t) <= 2);
    }
    if (fits_float) return CoordinateStorage::float32;
    return header_.encoding == PlyEncoding::ascii ? CoordinateStorage::decimal : CoordinateStorage::binary;
  }

  void read_vertices(const PlyElement& e) {
    if (e.count > max_element_count) throw bad_input("PLY header: {} vertices are more than fest can hold", e.count);
    Layout layout = vertex_layout(e);
    const bool normals = layout.has(Role::nx) || layout.has(Role::ny) || layout.has(Role::nz);
    const bool colors = layout.has(Role::red) || layout.has(Role::green) || layout.has(Role::blue);
    const bool texcoords = layout.has(Role::u) || layout.has(Role::v);
    if (normals) mesh_.request_vertex_normals();
    if (colors) mesh_.request_vertex_colors();
    set_point_storage(mesh_, storage_of(e, layout, Role::x, Role::y, Role::z));
    if (normals) set_normal_storage(mesh_, storage_of(e, layout, Role::nx, Role::ny, Role::nz));
    if (texcoords) mesh_.request_vertex_texcoords2D();
    mesh_.reserve(e.count, mesh_.n_edges(), mesh_.n_faces());
    for (std::uint64_t i = 0; i < e.count; ++i) {
      Mesh::Point point(0, 0, 0);
      Mesh::Normal normal(0, 0, 0);
      Mesh::Color color(0, 0, 0);
      Mesh::TexCoord2D uv(0, 0);
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (p.is_list) {
          skip_list(e, i, p);
          continue;
        }
        double v = value(e, i, p.type);
        switch (layout.roles[k]) {
          case Role::x: point[0] = v; break;
          case Role::y: point[1] = v; break;
          case Role::z: point[2] = v; break;
          case Role::nx: normal[0] = v; break;
          case Role::ny: normal[1] = v; break;
          case Role::nz: normal[2] = v; break;
          case Role::red: color[0] = to_color(v, p.type); break;
          case Role::green: color[1] = to_color(v, p.type); break;
          case Role::blue: color[2] = to_color(v, p.type); break;
          case Role::u: uv[0] = narrow_to_float(v); break;
          case Role::v: uv[1] = narrow_to_float(v); break;
          default: break;
        }
      }
      Mesh::VertexHandle vh = mesh_.add_vertex(point);
      if (normals) mesh_.set_normal(vh, normal);
      if (colors) mesh_.set_color(vh, color);
      if (texcoords) mesh_.set_texcoord2D(vh, uv);
    }
  }

  void read_faces(const PlyElement& e, Faces& faces) {
    if (e.count > max_element_count) throw bad_input("PLY header: {} faces are more than fest can hold", e.count);
    Layout layout = face_layout(e);
    const bool colors = layout.has(Role::red) || layout.has(Role::green) || layout.has(Role::blue);
    const std::uint64_t n_vertices = vertex_count();
    faces.offsets.reserve(e.count + 1);
    if (colors) faces.colors.reserve(e.count);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      Mesh::Color color(0, 0, 0);
      bool have_indices = false;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (layout.roles[k] == Role::indices && !have_indices) {
          // A second vertex_indices list (nonsense, but possible) is skipped.
          have_indices = true;
          std::uint64_t n = list_length(e, i, p);
          for (std::uint64_t j = 0; j < n; ++j) {
            double index = value(e, i, p.type);
            if (index < 0 || index >= static_cast<double>(n_vertices))
              throw bad_input("PLY face {}: vertex index {} is out of range (the file has {} vertices)", i + 1, index,
                              n_vertices);
            faces.indices.push_back(static_cast<std::uint32_t>(index));
          }
          continue;
        }
        if (p.is_list) {
          skip_list(e, i, p);
          continue;
        }
        double v = value(e, i, p.type);
        switch (layout.roles[k]) {
          case Role::red: color[0] = to_color(v, p.type); break;
          case Role::green: color[1] = to_color(v, p.type); break;
          case Role::blue: color[2] = to_color(v, p.type); break;
          default: break;
        }
      }
      faces.offsets.push_back(faces.indices.size());
      if (colors) faces.colors.push_back(color);
    }
  }


  void read_edges(const PlyElement& e) {
    std::size_t ends[2];
    edge_ends(e, ends);
    const std::uint64_t n_vertices = vertex_count();
    for (std::uint64_t i = 0; i < e.count; ++i) {
      std::vector<int> line(2, 0);
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (p.is_list) {
          skip_list(e, i, p);
          continue;
        }
        const double v = value(e, i, p.type);
        if (k != ends[0] && k != ends[1]) continue;
        if (v < 0 || v >= static_cast<double>(n_vertices))
          throw bad_input("PLY edge {}: vertex index {} is out of range (the file has {} vertices)", i + 1, v,
                          n_vertices);
        line[k == ends[0] ? 0 : 1] = static_cast<int>(v);
      }
      lines_.push_back(std::move(line));
    }
  }

 public:
  std::vector<std::vector<int>> lines_;

 private:
  void skip_element(const PlyElement& e) {
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const PlyProperty& p : e.properties) {
        if (p.is_list) skip_list(e, i, p);
        else value(e, i, p.type);
      }
  }

  Source& source_;
  const PlyHeader& header_;
  Mesh& mesh_;
};

// What the header declares that fest reads but does not keep (other vertex, face and
// edge properties, other elements), for unread_parts(): never dropped without a word.
std::vector<MeshPart> parts_not_kept(const PlyHeader& header) {
  std::vector<MeshPart> parts;
  for (const PlyElement& e : header.elements) {
    if (e.count == 0 || e.properties.empty()) continue;
    const bool lines = e.name == "edge" && edge_ends(e, nullptr);
    if (e.name != "vertex" && e.name != "face" && !lines) {
      parts.push_back({fmt::format("PLY '{}' elements", fest::quoted_bytes(e.name, 64)), e.count});
      continue;
    }
    std::string names;
    for (const PlyProperty& p : e.properties) {
      const bool kept = (e.name == "vertex" && vertex_role(p.name) != Role::skip) ||
                        (e.name == "face" && face_role(p.name) != Role::skip) ||
                        (lines && (p.name == "vertex1" || p.name == "vertex2"));
      if (!kept) names += (names.empty() ? "" : ", ") + fest::quoted_bytes(p.name, 64);  // may not be UTF-8
    }
    const char* plural = e.name == "vertex" ? "vertices" : e.name == "face" ? "faces" : "edges";
    if (!names.empty()) parts.push_back({fmt::format("{}' {} (PLY properties)", plural, names), e.count});
  }
  return parts;
}

}  // namespace

Mesh read_ply(std::string_view bytes) {
  PlyHeader header = parse_ply_header(bytes);
  Mesh mesh;
  Faces faces;
  std::vector<std::vector<int>> lines = with_ply_source(bytes, header, [&](auto& source) {
    BodyReader<std::decay_t<decltype(source)>> reader(source, header, mesh);
    reader.read_all(faces);
    return std::move(reader.lines_);
  });
  for (std::string& warning : header.warnings) add_read_warning(mesh, std::move(warning));
  if (std::vector<MeshPart> parts = parts_not_kept(header); !parts.empty()) set_unread_parts(mesh, std::move(parts));
  if (!lines.empty()) set_line_elements(mesh, std::move(lines));
  // Faces are added after every element is read: a file may list faces first.
  const std::size_t n_faces = faces.offsets.size() - 1;
  const bool colors = !faces.colors.empty();
  if (colors) mesh.request_face_colors();
  mesh.reserve(mesh.n_vertices(), mesh.n_vertices() + n_faces, n_faces);
  MeshBuilder builder(mesh, "PLY");
  for (std::size_t f = 0; f < n_faces; ++f) {
    Mesh::FaceHandle fh = builder.add_face(faces.indices.data() + faces.offsets[f],
                                           faces.offsets[f + 1] - faces.offsets[f], f + 1,
                                           colors ? &faces.colors[f] : nullptr);
    if (colors && fh.is_valid()) mesh.set_color(fh, faces.colors[f]);
  }
  builder.finish();
  return mesh;
}

}  // namespace fest::formats::mesh_detail

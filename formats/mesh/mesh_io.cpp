// Entry points of formats/mesh: dispatch on the format, option checks, describe_mesh.

#include "formats/mesh/mesh_io.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"

namespace fest::formats {

namespace {

// Where the files a scene refers to are looked for: beside the scene file, or nowhere.
std::optional<std::string> folder_of(const Input& in) {
  if (in.name.empty() || in.name == "-") return std::nullopt;
  const std::filesystem::path parent = std::filesystem::path(in.name).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

Mesh read_mesh_from(std::string_view bytes, Format format, const std::optional<std::string>& folder) {
  using namespace mesh_detail;
  silence_openmesh();
  if (kind_of(format) != Kind::mesh) throw bad_input("{} is not a mesh format", format_name(format));
  if (bytes.empty()) throw bad_input("{}: empty input", format_name(format));
  switch (format) {
    case Format::ply: return read_ply(bytes);
    case Format::off: return read_off(bytes);
    case Format::obj: return read_obj(bytes);
    case Format::stl: return read_stl(bytes);
    case Format::drc: return read_drc(bytes);
    default: break;
  }
  if (read_only_scene_format(format)) return read_assimp(bytes, format, folder);
  throw bad_input("{} is not a mesh format", format_name(format));
}

}  // namespace

Mesh MeshReader::operator()(std::string_view bytes, Format format) const {
  return read_mesh_from(bytes, format, std::nullopt);
}

Mesh MeshReader::operator()(const Input& in) const { return read_mesh_from(in.bytes, in.format, folder_of(in)); }

std::string write_mesh(const Mesh& mesh, Format format, const MeshWriteOptions& options) {
  using namespace mesh_detail;
  silence_openmesh();
  if (options.draco_position_bits < 0 || options.draco_position_bits > 30)
    throw usage_error("Draco position bits must be 0 (lossless) to 30, not {}", options.draco_position_bits);
  if (options.draco_normal_bits < 0 || options.draco_normal_bits > 30)
    throw usage_error("Draco normal bits must be 0 (unquantized) to 30, not {}", options.draco_normal_bits);
  if (options.draco_texcoord_bits < 0 || options.draco_texcoord_bits > 30)
    throw usage_error("Draco texture coordinate bits must be 0 (unquantized) to 30, not {}",
                      options.draco_texcoord_bits);
  if (options.draco_speed < 0 || options.draco_speed > 10)
    throw usage_error("Draco speed must be 0 to 10, not {}", options.draco_speed);
  if (!options.drop_unrepresentable) {
    const std::vector<MeshPart> parts = unwritable_parts(mesh, format);
    if (!parts.empty()) {
      std::string what;
      for (const MeshPart& part : parts) what += (what.empty() ? "" : ", ") + part.describe();
      throw bad_input("{} cannot hold the mesh's {}", format_name(format), what);
    }
  }
  switch (format) {
    case Format::ply: return write_ply(mesh, options.ascii, options.precision);
    case Format::off: return write_off(mesh);
    case Format::obj: return write_obj(mesh);
    case Format::stl: return write_stl(mesh, options.ascii);
    case Format::drc: return write_drc(mesh, options);
    default: break;
  }
  throw bad_input("cannot write a mesh as {}", format_name(format));
}

std::vector<std::vector<int>> skipped_face_list(const Mesh& mesh) {
  OpenMesh::MPropHandleT<std::vector<std::vector<int>>> handle;
  if (!mesh.get_property_handle(handle, skipped_face_list_property)) return {};
  return mesh.property(handle);
}

std::vector<std::vector<int>> extra_faces(const Mesh& mesh) {
  OpenMesh::MPropHandleT<std::vector<std::vector<int>>> handle;
  if (!mesh.get_property_handle(handle, extra_faces_property)) return {};
  return mesh.property(handle);
}

std::string MeshPart::describe() const { return fmt::format("{} {}", count, what); }

std::vector<std::vector<int>> faces_beside(const Mesh& mesh) {
  std::vector<std::vector<int>> extra = extra_faces(mesh);
  return extra.empty() ? skipped_face_list(mesh) : extra;
}

std::size_t total_faces(const Mesh& mesh) { return mesh.n_faces() + faces_beside(mesh).size(); }

std::size_t line_segments(const Mesh& mesh) {
  std::size_t n = 0;
  for (const auto& line : line_elements(mesh)) n += line.empty() ? 0 : line.size() - 1;
  return n;
}

std::size_t point_count(const Mesh& mesh) {
  std::size_t n = 0;
  for (const auto& points : point_elements(mesh)) n += points.size();
  return n;
}

std::vector<MeshPart> unwritable_parts(const Mesh& mesh, Format format) {
  std::vector<MeshPart> parts;
  const bool holds_lines = format == Format::obj || format == Format::ply;
  const bool holds_points = format == Format::obj;
  const bool holds_small_faces = format == Format::obj || format == Format::ply || format == Format::off;
  const auto lines = line_elements(mesh);
  if (!holds_lines && !lines.empty())
    parts.push_back({fmt::format("line elements ({} segments)", line_segments(mesh)), lines.size()});
  if (format == Format::ply) {
    // PLY edges join two vertices: a line element of one vertex (or none) has no edge.
    std::size_t short_lines = 0;
    for (const auto& line : lines) short_lines += line.size() < 2 ? 1 : 0;
    if (short_lines > 0) parts.push_back({"line elements of fewer than 2 vertices", short_lines});
  }
  if (!holds_points)
    if (const auto points = point_elements(mesh); !points.empty())
      parts.push_back({fmt::format("point elements ({} points)", point_count(mesh)), points.size()});
  if (!holds_small_faces) {
    // Only faces kept beside the halfedge mesh can have fewer than three vertices.
    std::size_t small = 0;
    for (const auto& face : extra_faces(mesh)) small += face.size() < 3 ? 1 : 0;
    if (small > 0) parts.push_back({"faces of fewer than 3 vertices", small});
  }
  return parts;
}

std::size_t skipped_faces(const Mesh& mesh) {
  OpenMesh::MPropHandleT<std::size_t> handle;
  if (!mesh.get_property_handle(handle, skipped_faces_property)) return 0;
  return mesh.property(handle);
}

nlohmann::json describe_mesh(const Mesh& mesh) {
  nlohmann::json info;
  std::size_t n_vertices = 0, n_faces = 0;
  bool triangles = true;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -std::numeric_limits<double>::infinity();
  }
  for (auto v : mesh.vertices()) {
    ++n_vertices;
    const Mesh::Point& p = mesh.point(v);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);  // NaN coordinates leave the box alone
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  for (auto f : mesh.faces()) {
    ++n_faces;
    triangles = triangles && mesh.valence(f) == 3;
  }
  std::size_t n_edges = 0;
  for (auto e : mesh.edges()) {
    (void)e;
    ++n_edges;
  }
  const std::vector<std::vector<int>> beside = faces_beside(mesh);
  for (const auto& face : beside) triangles = triangles && face.size() == 3;
  info["vertices"] = n_vertices;
  info["faces"] = n_faces + beside.size();
  info["edges"] = n_edges;
  info["triangles"] = triangles;
  if (n_vertices > 0 && lo[0] <= hi[0])
    info["bbox"] = {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}};
  else
    info["bbox"] = nullptr;
  nlohmann::json attributes = nlohmann::json::array();
  if (mesh.has_vertex_normals()) attributes.push_back("vertex_normals");
  if (mesh.has_vertex_colors()) attributes.push_back("vertex_colors");
  if (mesh.has_vertex_texcoords2D()) attributes.push_back("vertex_texcoords");
  if (mesh.has_face_colors()) attributes.push_back("face_colors");
  if (mesh.has_face_normals()) attributes.push_back("face_normals");
  info["attributes"] = attributes;
  if (std::size_t skipped = skipped_faces(mesh); skipped > 0) info["skipped_faces"] = skipped;
  if (const auto lines = line_elements(mesh); !lines.empty()) {
    info["lines"] = lines.size();
    info["line_segments"] = line_segments(mesh);
  }
  if (const auto points = point_elements(mesh); !points.empty()) info["points"] = point_count(mesh);
  if (const auto parts = unread_parts(mesh); !parts.empty()) {
    nlohmann::json not_kept = nlohmann::json::array();
    for (const MeshPart& part : parts) not_kept.push_back(part.describe());
    info["not_kept"] = not_kept;
  }
  return info;
}

}  // namespace fest::formats

// Entry points of formats/mesh: dispatch on the format, option checks, describe_mesh.

#include "formats/mesh/mesh_io.hpp"

#include <algorithm>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"

namespace fest::formats {

Mesh read_mesh(std::string_view bytes, Format format) {
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
  throw bad_input("{} is not a mesh format", format_name(format));
}

std::string write_mesh(const Mesh& mesh, Format format, const MeshWriteOptions& options) {
  using namespace mesh_detail;
  silence_openmesh();
  if (options.draco_position_bits < 0 || options.draco_position_bits > 30)
    throw usage_error("Draco position bits must be 0 (lossless) to 30, not {}", options.draco_position_bits);
  if (options.draco_speed < 0 || options.draco_speed > 10)
    throw usage_error("Draco speed must be 0 to 10, not {}", options.draco_speed);
  switch (format) {
    case Format::ply: return write_ply(mesh, options.ascii);
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

void set_extra_faces(Mesh& mesh, std::vector<std::vector<int>> faces) {
  OpenMesh::MPropHandleT<std::vector<std::vector<int>>> handle;
  if (!mesh.get_property_handle(handle, extra_faces_property)) mesh.add_property(handle, extra_faces_property);
  mesh.property(handle) = std::move(faces);
}

std::vector<std::vector<int>> extra_faces(const Mesh& mesh) {
  OpenMesh::MPropHandleT<std::vector<std::vector<int>>> handle;
  if (!mesh.get_property_handle(handle, extra_faces_property)) return {};
  return mesh.property(handle);
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
  info["vertices"] = n_vertices;
  info["faces"] = n_faces;
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
  return info;
}

}  // namespace fest::formats

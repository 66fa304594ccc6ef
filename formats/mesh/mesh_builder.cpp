#include "formats/mesh/mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <cstdlib>
#include <limits>
#include <string>

#include <OpenMesh/Core/System/omstream.hh>
#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::formats::mesh_detail {

void silence_openmesh() {
  static const bool silenced = [] {
    omerr().disable();
    omlog().disable();
    omout().disable();
    return true;
  }();
  (void)silenced;
}

Mesh::FaceHandle MeshBuilder::add_face(const std::uint32_t* indices, std::size_t count, std::size_t face_number,
                                       const Mesh::Color* color) {
  const std::size_t n_vertices = mesh_.n_vertices();
  handles_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    if (indices[i] >= n_vertices) {
      throw bad_input("{} face {}: vertex index {} is out of range (the mesh has {} vertices)", label_, face_number,
                      indices[i], n_vertices);
    }
    handles_.push_back(Mesh::VertexHandle(static_cast<int>(indices[i])));
  }
  // OpenMesh's add_face assumes at least three distinct vertices (it only asserts,
  // which a release build ignores, and a repeated vertex corrupts the halfedges).
  bool repeated = false;
  if (count <= 16) {
    for (std::size_t i = 0; i < count && !repeated; ++i)
      for (std::size_t j = i + 1; j < count && !repeated; ++j) repeated = indices[i] == indices[j];
  } else {  // a huge polygon must not cost quadratic time
    sorted_.assign(indices, indices + count);
    std::sort(sorted_.begin(), sorted_.end());
    repeated = std::adjacent_find(sorted_.begin(), sorted_.end()) != sorted_.end();
  }
  Mesh::FaceHandle face;
  if (count >= 3 && !repeated) face = mesh_.add_face(handles_);
  if (!face.is_valid()) {
    ++skipped_;
    skipped_list_.emplace_back(indices, indices + count);
    skipped_places_.push_back(face_number - 1);
    skipped_colors_.push_back(color ? *color : Mesh::Color(255, 255, 255));
  }
  return face;
}

namespace {

template <typename T>
void set_mesh_property(Mesh& mesh, const char* name, T value) {
  OpenMesh::MPropHandleT<T> handle;
  if (!mesh.get_property_handle(handle, name)) mesh.add_property(handle, name);
  mesh.property(handle) = std::move(value);
}

template <typename T>
T get_mesh_property(const Mesh& mesh, const char* name) {
  OpenMesh::MPropHandleT<T> handle;
  if (!mesh.get_property_handle(handle, name)) return T{};
  return mesh.property(handle);
}

constexpr const char* skipped_places_property = "fest:skipped_face_places";
constexpr const char* skipped_colors_property = "fest:skipped_face_colors";
constexpr const char* extra_places_property = "fest:extra_face_places";
constexpr const char* extra_colors_property = "fest:extra_face_colors";
constexpr const char* point_storage_property = "fest:point_storage";
constexpr const char* normal_storage_property = "fest:normal_storage";
constexpr const char* read_warnings_property = "fest:read_warnings";

}  // namespace

void MeshBuilder::finish() {
  if (skipped_ > 0) set_skipped_faces_property(mesh_, skipped_);
  if (!skipped_list_.empty()) {
    set_mesh_property(mesh_, skipped_face_list_property, std::move(skipped_list_));
    set_mesh_property(mesh_, skipped_places_property, std::move(skipped_places_));
    set_mesh_property(mesh_, skipped_colors_property, std::move(skipped_colors_));
  }
}

FacesBeside extra_faces_to_write(const Mesh& mesh) {
  FacesBeside beside;
  beside.faces = get_mesh_property<std::vector<std::vector<int>>>(mesh, extra_faces_property);
  beside.places = get_mesh_property<std::vector<std::size_t>>(mesh, extra_places_property);
  beside.colors = get_mesh_property<std::vector<Mesh::Color>>(mesh, extra_colors_property);
  if (beside.places.size() != beside.faces.size()) beside.places.clear();  // set_extra_faces(): append
  if (beside.colors.size() != beside.faces.size()) beside.colors.clear();
  return beside;
}

}  // namespace fest::formats::mesh_detail

namespace fest::formats {

void carry_skipped_faces(Mesh& mesh) {
  using namespace mesh_detail;
  set_mesh_property(mesh, extra_faces_property, skipped_face_list(mesh));
  set_mesh_property(mesh, extra_places_property, get_mesh_property<std::vector<std::size_t>>(mesh, skipped_places_property));
  set_mesh_property(mesh, extra_colors_property, get_mesh_property<std::vector<Mesh::Color>>(mesh, skipped_colors_property));
}

void set_extra_faces(Mesh& mesh, std::vector<std::vector<int>> faces) {
  using namespace mesh_detail;
  set_mesh_property(mesh, extra_faces_property, std::move(faces));
  set_mesh_property(mesh, extra_places_property, std::vector<std::size_t>{});
  set_mesh_property(mesh, extra_colors_property, std::vector<Mesh::Color>{});
}

std::vector<std::vector<int>> line_elements(const Mesh& mesh) {
  return mesh_detail::get_mesh_property<std::vector<std::vector<int>>>(mesh, line_elements_property);
}
std::vector<std::vector<int>> point_elements(const Mesh& mesh) {
  return mesh_detail::get_mesh_property<std::vector<std::vector<int>>>(mesh, point_elements_property);
}
void set_line_elements(Mesh& mesh, std::vector<std::vector<int>> lines) {
  mesh_detail::set_mesh_property(mesh, line_elements_property, std::move(lines));
}
void set_point_elements(Mesh& mesh, std::vector<std::vector<int>> points) {
  mesh_detail::set_mesh_property(mesh, point_elements_property, std::move(points));
}

std::vector<MeshPart> unread_parts(const Mesh& mesh) {
  return mesh_detail::get_mesh_property<std::vector<MeshPart>>(mesh, "fest:unread_parts");
}

std::vector<std::string> read_warnings(const Mesh& mesh) {
  return mesh_detail::get_mesh_property<std::vector<std::string>>(mesh, mesh_detail::read_warnings_property);
}

}  // namespace fest::formats

namespace fest::formats::mesh_detail {

void add_read_warning(Mesh& mesh, std::string message) {
  auto warnings = read_warnings(mesh);
  warnings.push_back(std::move(message));
  set_mesh_property(mesh, read_warnings_property, std::move(warnings));
}

void set_unread_parts(Mesh& mesh, std::vector<MeshPart> parts) {
  set_mesh_property(mesh, "fest:unread_parts", std::move(parts));
}

void set_point_storage(Mesh& mesh, CoordinateStorage storage) {
  set_mesh_property(mesh, point_storage_property, static_cast<int>(storage));
}
void set_normal_storage(Mesh& mesh, CoordinateStorage storage) {
  set_mesh_property(mesh, normal_storage_property, static_cast<int>(storage));
}

bool decimal_fits_float(double value) {
  if (exactly_float(&value, 1)) return true;
  if (!std::isfinite(value) || std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) return false;
  // The shortest text of the nearest float; parsing it as a double gives back `value`
  // exactly when the file's text and the float's text are the same number.
  char text[32];
  const auto end = fmt::format_to_n(text, sizeof text - 1, "{}", static_cast<float>(value)).out;
  *end = '\0';
  return std::strtod(text, nullptr) == value;
}

namespace {

template <class Values>
bool storage_allows_float(const Mesh& mesh, const char* property, CoordinatePrecision precision, Values values) {
  if (precision == CoordinatePrecision::float32) return true;
  if (precision == CoordinatePrecision::float64) return false;
  const auto storage = static_cast<CoordinateStorage>(get_mesh_property<int>(mesh, property));
  for (auto v : mesh.vertices()) {
    const auto& value = values(v);
    for (int k = 0; k < 3; ++k) {
      const double x = value[k];
      // Values are checked even for float storage: a tool may have computed new ones.
      const bool text = storage == CoordinateStorage::decimal || storage == CoordinateStorage::float32;
      if (text ? !decimal_fits_float(x) : !exactly_float(&x, 1)) return false;
    }
  }
  return true;
}

}  // namespace

bool write_points_as_float(const Mesh& mesh, CoordinatePrecision precision) {
  return storage_allows_float(mesh, point_storage_property, precision,
                              [&](Mesh::VertexHandle v) -> const Mesh::Point& { return mesh.point(v); });
}

bool write_normals_as_float(const Mesh& mesh, CoordinatePrecision precision) {
  if (!mesh.has_vertex_normals()) return true;
  return storage_allows_float(mesh, normal_storage_property, precision,
                              [&](Mesh::VertexHandle v) -> const Mesh::Normal& { return mesh.normal(v); });
}

void set_skipped_faces_property(Mesh& mesh, std::size_t count) {
  OpenMesh::MPropHandleT<std::size_t> handle;
  if (!mesh.get_property_handle(handle, skipped_faces_property)) mesh.add_property(handle, skipped_faces_property);
  mesh.property(handle) = count;
}

void append_number(std::string& out, double value) { fmt::format_to(std::back_inserter(out), "{}", value); }
void append_number(std::string& out, float value) { fmt::format_to(std::back_inserter(out), "{}", value); }

bool exactly_float(const double* values, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    double v = values[i];
    if (std::isnan(v)) continue;
    // Out-of-range doubles would overflow the float (UB), so test the range first.
    if (std::isfinite(v) && std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max())) return false;
    if (static_cast<double>(static_cast<float>(v)) != v) return false;
  }
  return true;
}

bool points_are_floats(const Mesh& mesh) {
  for (auto v : mesh.vertices())
    if (!exactly_float(mesh.point(v).data(), 3)) return false;
  return true;
}

bool normals_are_floats(const Mesh& mesh) {
  if (!mesh.has_vertex_normals()) return true;
  for (auto v : mesh.vertices())
    if (!exactly_float(mesh.normal(v).data(), 3)) return false;
  return true;
}

float narrow_to_float(double value) {
  constexpr double max = static_cast<double>(std::numeric_limits<float>::max());
  if (std::isfinite(value) && std::fabs(value) > max) {
    // Values just above max still round to max (round to nearest); beyond half an
    // ulp past it they round to infinity. Either way no UB.
    const double limit = max + std::ldexp(1.0, 127 - 24);
    if (std::fabs(value) < limit) return value > 0 ? std::numeric_limits<float>::max() : -std::numeric_limits<float>::max();
    return value > 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
  }
  return static_cast<float>(value);
}

std::uint8_t color_from_unit(double value) {
  if (!(value > 0.0)) return 0;  // also NaN
  if (value >= 1.0) return 255;
  return static_cast<std::uint8_t>(std::lround(value * 255.0));
}

std::uint8_t color_from_byte_range(double value) {
  if (!(value > 0.0)) return 0;
  if (value >= 255.0) return 255;
  return static_cast<std::uint8_t>(std::lround(value));
}

const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage) {
  bool any_deleted = false;
  if (mesh.has_vertex_status())
    for (auto v : mesh.all_vertices()) any_deleted = any_deleted || mesh.status(v).deleted();
  if (mesh.has_face_status())
    for (auto f : mesh.all_faces()) any_deleted = any_deleted || mesh.status(f).deleted();
  if (!any_deleted) return mesh;
  storage.emplace(mesh);
  // garbage_collection() needs status on every element kind; requesting it where the
  // caller had none adds fresh (not deleted) flags.
  storage->request_vertex_status();
  storage->request_edge_status();
  storage->request_halfedge_status();
  storage->request_face_status();
  storage->garbage_collection();
  return *storage;
}

}  // namespace fest::formats::mesh_detail

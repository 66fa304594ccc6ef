#include "formats/mesh/mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

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

Mesh::FaceHandle MeshBuilder::add_face(const std::uint32_t* indices, std::size_t count, std::size_t face_number) {
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
  }
  return face;
}

void MeshBuilder::finish() {
  if (skipped_ > 0) set_skipped_faces_property(mesh_, skipped_);
  if (!skipped_list_.empty()) {
    OpenMesh::MPropHandleT<std::vector<std::vector<int>>> handle;
    if (!mesh_.get_property_handle(handle, skipped_face_list_property)) mesh_.add_property(handle, skipped_face_list_property);
    mesh_.property(handle) = std::move(skipped_list_);
  }
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

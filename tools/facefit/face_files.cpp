#include "face_files.hpp"

#include <cstdlib>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/facemodel/landmarks_io.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/input.hpp"
#include "formats/mesh/indexed_ply.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

void warn(const std::string& message) { fest::warn(tool, message); }

std::string model_path(const std::string& option) {
  if (!option.empty()) return option;
  if (const char* env = std::getenv("FACEFIT_MODEL"); env && *env) return env;
  throw usage_error("no model: give -m MODEL.mmb or set FACEFIT_MODEL");
}

namespace {

// The library refuses a basis whose columns are not unit length in its own terms; when
// renormalising would have accepted the model, the message also names the flag that does.
[[noreturn]] void rethrow_with_fix_basis_hint(const Error& e, bool fix_would_pass) {
  if (!fix_would_pass) throw e;
  throw Error(e.status(), std::string(e.what()) + "; --fix-basis renormalises it");
}

}  // namespace

facefit::CheckResult check_model_naming_flags(facefit::Model& m, bool fix_basis) {
  try {
    return facefit::check_model(m, fix_basis);
  } catch (const Error& e) {
    if (fix_basis || e.status() != Status::bad_input) throw;
    facefit::Model copy = m;  // renormalising gives the copy its own basis storage
    bool fix_would_pass = true;
    try {
      facefit::check_model(copy, true);
    } catch (const Error&) {
      fix_would_pass = false;
    }
    rethrow_with_fix_basis_hint(e, fix_would_pass);
  }
}

facefit::Model load_model(const std::string& option, bool fix_basis) {
  std::string warnings;
  formats::MmbReadOptions o;
  o.fix_basis = fix_basis;
  const std::string path = model_path(option);
  facefit::Model m;
  try {
    m = formats::read_mmb(path, o, &warnings);
  } catch (const Error& e) {
    if (fix_basis || e.status() != Status::bad_input) throw;
    bool fix_would_pass = true;
    try {
      formats::MmbReadOptions fix;
      fix.fix_basis = true;
      formats::read_mmb(path, fix);
    } catch (const Error&) {
      fix_would_pass = false;
    }
    rethrow_with_fix_basis_hint(e, fix_would_pass);
  }
  if (!warnings.empty()) warn(warnings.substr(0, warnings.size() - 2));
  return m;
}

Mesh shape_to_mesh(const Eigen::VectorXd& shape, int dims, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  Mesh mesh;
  const Eigen::Index p = shape.size() / dims;
  std::vector<Mesh::VertexHandle> vh(static_cast<std::size_t>(p));
  for (Eigen::Index j = 0; j < p; ++j)
    vh[static_cast<std::size_t>(j)] = mesh.add_vertex(Mesh::Point(shape(dims * j), shape(dims * j + 1), dims == 3 ? shape(dims * j + 2) : 0.0));
  for (const auto& t : triangles) mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
  return mesh;
}

Eigen::VectorXd read_shape(const std::string& path, std::vector<std::array<std::uint32_t, 3>>* triangles) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::mesh) throw bad_input("'{}' is not a mesh ({})", path, formats::format_name(in.format));
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  Eigen::VectorXd v(3 * static_cast<Eigen::Index>(mesh.n_vertices()));
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    for (int e = 0; e < 3; ++e) v(3 * vh.idx() + e) = p[e];
  }
  if (!v.allFinite()) throw bad_input("non-finite vertex coordinates ({})", path);
  if (triangles) {
    triangles->clear();
    for (auto fh : mesh.faces()) {
      std::vector<std::uint32_t> idx;
      for (auto fv : mesh.fv_range(fh)) idx.push_back(static_cast<std::uint32_t>(fv.idx()));
      for (std::size_t i = 1; i + 1 < idx.size(); ++i) triangles->push_back({idx[0], idx[i], idx[i + 1]});
    }
  }
  return v;
}

MeshOutput parse_mesh_output(const std::string& word) {
  MeshOutput m;
  m.format = formats::output_format_from_name(word == "plya" ? "ply" : word);
  if (formats::kind_of(m.format.format) != formats::Kind::mesh) throw usage_error("--to {}: not a mesh format", word);
  m.ascii = word == "plya";
  m.direct_ply = word == "ply" || word == ".ply";
  return m;
}

void write_mesh_to(const Mesh& mesh, const std::string& path, const std::optional<MeshOutput>& to) {
  formats::OutputFormat out{formats::Format::ply, false};
  if (to) {
    out = to->format;
  } else if (!is_stdio(path)) {
    out = formats::output_format_from_path(path);
  }
  if (formats::kind_of(out.format) != formats::Kind::mesh) throw usage_error("--to {}: not a mesh format", "");
  formats::MeshWriteOptions w;
  w.ascii = to && to->ascii;
  formats::store_output(path, formats::write_mesh(mesh, out.format, w), out.gzip);
}

bool writes_binary_ply(const std::string& path, const std::optional<MeshOutput>& to) {
  if (to) return to->direct_ply;
  if (is_stdio(path)) return true;
  const formats::OutputFormat out = formats::output_format_from_path(path);
  return out.format == formats::Format::ply && !out.gzip;
}

void write_shape(const Eigen::VectorXd& shape, int dims, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                 const std::string& path, const std::optional<MeshOutput>& to) {
  if (!writes_binary_ply(path, to)) return write_mesh_to(shape_to_mesh(shape, dims, triangles), path, to);
  const std::size_t p = static_cast<std::size_t>(shape.size() / dims);
  std::vector<float> xyz(3 * p, 0.0f);
  for (std::size_t j = 0; j < p; ++j)
    for (int e = 0; e < dims; ++e) xyz[3 * j + static_cast<std::size_t>(e)] = static_cast<float>(shape(static_cast<Eigen::Index>(j) * dims + e));
  write_output(path, formats::write_indexed_ply(xyz, triangles));
}

std::string read_text(const std::string& path) { return read_input(path); }

std::vector<std::string> read_list(const std::string& path) {
  const std::string text = read_input(path);
  std::string dir;
  if (const auto slash = path.rfind('/'); slash != std::string::npos) dir = path.substr(0, slash + 1);
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    out.push_back(line[0] == '/' ? line : dir + line);
  }
  if (out.empty()) throw bad_input("list '{}' names no files", path);
  return out;
}

std::vector<std::uint32_t> read_vertex_indices(const std::string& path) {
  std::vector<std::uint32_t> out;
  for (const auto& nv : formats::read_vertex_set(read_input(path), path)) out.push_back(nv.vertex);
  return out;
}

facefit::LandmarkMap read_map(const std::string& path) { return formats::read_landmark_map(read_input(path), path); }

}  // namespace fest::facefit_tool

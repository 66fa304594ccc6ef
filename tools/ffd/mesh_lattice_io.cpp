#include "mesh_lattice_io.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "ffd/joints.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"

namespace fest::ffd_tool {

// A lattice file: JSON when it starts with '{', else PyGeM .prm (docs/ffd.md 4).
Lattice load_lattice(const std::string& path) {
  if (path.empty()) throw usage_error("--lattice is required");
  const std::string text = read_input(path);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  try {
    if (first != std::string::npos && text[first] == '{') return ffd::decode_lattice_json(text);
    return ffd::decode_pygem_prm(text);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), path));
  }
}

Mesh load_mesh(const std::string& path, formats::Format* format) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("{} input is not a mesh ({})", formats::format_name(in.format), in.name);
  Mesh m = formats::parse(in, formats::read_mesh);
  if (format) *format = in.format;
  return m;
}

formats::OutputFormat output_format(const std::string& to, const std::string& path, formats::Format input) {
  formats::OutputFormat f{input, false};
  if (!to.empty()) f = formats::output_format_from_name(to);
  else if (!is_stdio(path)) f = formats::output_format_from_path(path);
  if (formats::kind_of(f.format) != formats::Kind::mesh) throw usage_error("output format {} is not a mesh format", formats::format_name(f.format));
  return f;
}

void check_size(const Lattice& l, bool allow_large) {
  if (l.size() > 64u * 64u * 64u && !allow_large)
    throw runtime_failure("lattice of {} control points exceeds 64^3; --allow-large permits it", l.size());
}

std::vector<Eigen::Vector3d> points_of(const Mesh& m) {
  std::vector<Eigen::Vector3d> p;
  p.reserve(m.n_vertices());
  for (const auto v : m.vertices()) p.emplace_back(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
  return p;
}

void set_points(Mesh& m, const std::vector<Eigen::Vector3d>& p) {
  for (const auto v : m.vertices()) {
    const Eigen::Vector3d& x = p[static_cast<std::size_t>(v.idx())];
    m.set_point(v, OpenMesh::Vec3d(x[0], x[1], x[2]));
  }
}

// A third of the incident face areas per vertex (the weights a_v of docs/ffd.md 2.4).
std::vector<double> vertex_areas(const Mesh& m) {
  std::vector<double> a(m.n_vertices(), 0.0);
  for (const auto f : m.faces()) {
    std::vector<OpenMesh::Vec3d> c;
    std::vector<int> idx;
    for (const auto v : m.fv_range(f)) { c.push_back(m.point(v)); idx.push_back(v.idx()); }
    double area = 0;
    for (std::size_t i = 1; i + 1 < c.size(); ++i) area += 0.5 * OpenMesh::cross(c[i] - c[0], c[i + 1] - c[0]).norm();
    for (const int i : idx) a[static_cast<std::size_t>(i)] += area / static_cast<double>(idx.size());
  }
  return a;
}

void update_normals(Mesh& m, NormalsMode mode, const ffd::Deformer* d, const std::vector<Eigen::Vector3d>& rest,
                    ffd::Outside outside) {
  if (!m.has_vertex_normals()) return;
  if (mode == NormalsMode::jacobian && d) {
    for (const auto v : m.vertices()) {
      const Eigen::Matrix3d J = d->jacobian(rest[static_cast<std::size_t>(v.idx())], outside);
      const auto& n0 = m.normal(v);
      Eigen::Vector3d n = J.inverse().transpose() * Eigen::Vector3d(n0[0], n0[1], n0[2]);
      if (n.norm() > 0) n.normalize();
      m.set_normal(v, OpenMesh::Vec3d(n[0], n[1], n[2]));
    }
    return;
  }
  const bool had_face_normals = m.has_face_normals();
  if (!had_face_normals) m.request_face_normals();
  m.update_face_normals();
  m.update_vertex_normals();
  if (!had_face_normals) m.release_face_normals();
}

std::vector<std::size_t> read_fixed(const std::string& path, const Lattice& l) {
  std::vector<std::size_t> out;
  if (path.empty()) return out;
  std::istringstream in(read_input(path));
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t\r")] == '#') continue;
    std::istringstream row(line);
    long long i, j, k;
    if (!(row >> i >> j >> k)) throw bad_input("fixed control point line {} is not 'i j k' ({})", n, path);
    if (i < 0 || j < 0 || k < 0 || i >= l.dims[0] || j >= l.dims[1] || k >= l.dims[2])
      throw bad_input("fixed control point line {} is outside the lattice ({})", n, path);
    out.push_back(l.index(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k)));
  }
  return out;
}

std::string object_output(const std::string& pattern, const std::string& name, std::size_t objects) {
  if (objects <= 1) return pattern;
  const std::size_t at = pattern.find("%s");
  if (at == std::string::npos) throw usage_error("-o needs %s (the object name) when there are {} objects", objects);
  return pattern.substr(0, at) + name + pattern.substr(at + 2);
}

// The pattern's one "%d" or "%0Nd" replaced by the frame number (no printf: the pattern
// is user text).
std::string frame_name(const std::string& pattern, long frame) {
  const std::size_t at = pattern.find('%');
  if (at == std::string::npos) throw usage_error("-o needs a frame pattern with %d (e.g. frames/f%04d.ply)");
  std::size_t i = at + 1;
  int width = 0;
  while (i < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[i])) && width < 100) width = width * 10 + (pattern[i++] - '0');
  if (i >= pattern.size() || pattern[i] != 'd' || pattern.find('%', i) != std::string::npos)
    throw usage_error("-o: the frame pattern must hold exactly one %d or %0Nd ('{}')", pattern);
  std::string num = std::to_string(frame);
  if (num.size() < static_cast<std::size_t>(width)) num.insert(0, static_cast<std::size_t>(width) - num.size(), '0');
  return pattern.substr(0, at) + num + pattern.substr(i + 1);
}

}  // namespace fest::ffd_tool

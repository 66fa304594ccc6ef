#include "ffd_app.hpp"

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
#include "ffd/lattice.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::ffd_tool {

namespace {

using ffd::Lattice;

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

Mesh load_mesh(const std::string& path, formats::Format* format = nullptr) {
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

ffd::Outside outside_of(const std::string& s) {
  if (s == "none") return ffd::Outside::none;
  if (s == "clamp") return ffd::Outside::clamp;
  throw usage_error("--outside: unknown '{}' (none, clamp)", s);
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

void update_normals(Mesh& m, const std::string& mode, const ffd::Deformer* d, const std::vector<Eigen::Vector3d>& rest,
                    ffd::Outside outside) {
  if (!m.has_vertex_normals()) return;
  if (mode == "jacobian" && d) {
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

}  // namespace

int run_init(const InitOptions& o) {
  if (o.dims.size() != 3) throw usage_error("--dims takes L,M,N");
  for (const int d : o.dims)
    if (d < 2 || d > ffd::max_axis_points) throw usage_error("--dims: {} is outside 2..{}", d, ffd::max_axis_points);
  if (!(o.pad >= 0) || o.pad > 10) throw usage_error("--pad {} is outside 0..10", o.pad);
  const ffd::Basis basis = ffd::basis_from_name(o.basis.c_str());
  const Mesh m = load_mesh(o.input);
  if (m.n_vertices() == 0) throw bad_input("the mesh has no vertices ({})", o.input);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Eigen::Vector3d& p : points_of(m)) {
    if (!p.allFinite()) throw bad_input("the mesh has a non-finite coordinate ({})", o.input);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Eigen::Vector3d ext = hi - lo;
  const double scale = std::max(ext.maxCoeff(), 1e-12);
  for (int a = 0; a < 3; ++a) ext[a] = std::max(ext[a], 1e-6 * scale);  // a flat mesh still gets a box
  Lattice l;
  l.origin = lo - o.pad * ext;
  for (int a = 0; a < 3; ++a) l.axes[static_cast<std::size_t>(a)] = Eigen::Vector3d::Unit(a) * ext[a] * (1 + 2 * o.pad);
  for (int a = 0; a < 3; ++a) l.dims[static_cast<std::size_t>(a)] = o.dims[static_cast<std::size_t>(a)];
  l.basis.fill(basis);
  write_output(o.output, ffd::encode_lattice_json(l));
  return 0;
}

int run_apply(const ApplyOptions& o) {
  using Clock = std::chrono::steady_clock;
  const int threads = resolve_threads(o.threads);
  const ffd::Outside outside = outside_of(o.outside);
  if (o.normals != "recompute" && o.normals != "jacobian") throw usage_error("--normals: unknown '{}' (recompute, jacobian)", o.normals);
  Lattice lattice = load_lattice(o.lattice);
  check_size(lattice, o.allow_large);

  // Objects: --in NAME=FILE, else the one mesh on -/input.
  struct Object {
    std::string name, path, mode = "deform";
    Mesh mesh;
    formats::Format format = formats::Format::ply;
  };
  std::vector<Object> objects;
  for (const std::string& spec : o.inputs) {
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0) throw usage_error("--in takes NAME=FILE ('{}')", spec);
    objects.push_back({spec.substr(0, eq), spec.substr(eq + 1), "deform", {}, formats::Format::ply});
  }
  if (objects.empty()) objects.push_back({"mesh", o.input, "deform", {}, formats::Format::ply});
  for (const std::string& spec : o.objects) {
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos) throw usage_error("--object takes NAME=deform|rigid|ignore ('{}')", spec);
    const std::string name = spec.substr(0, eq), mode = spec.substr(eq + 1);
    if (mode != "deform" && mode != "rigid" && mode != "ignore") throw usage_error("--object {}: unknown mode '{}'", name, mode);
    auto it = std::find_if(objects.begin(), objects.end(), [&](const Object& x) { return x.name == name; });
    if (it == objects.end()) throw usage_error("--object: no object named '{}'", name);
    it->mode = mode;
  }
  for (Object& ob : objects) ob.mesh = load_mesh(ob.path, &ob.format);

  nlohmann::json report;
  if (!o.joints.empty()) {
    const std::vector<ffd::Joint> joints = [&] {
      try {
        return ffd::decode_joints(read_input(o.joints));
      } catch (const Error& e) {
        if (e.status() != Status::bad_input) throw;
        throw Error(e.status(), with_location(e.what(), o.joints));
      }
    }();
    const ffd::JointSolve js = ffd::preserve_joints(lattice, joints, read_fixed(o.fixed_cp, lattice));
    if (!js.exact) {
      if (o.strict) throw runtime_failure("{} joints exceed the rank {} of the lattice; residual {:g}", joints.size(), js.rank, js.max_error_after);
      warn("ffd", fmt::format("{} joints exceed the rank {} of the lattice: least squares, residual {:g}", joints.size(), js.rank,
                              js.max_error_after));
    }
    report["joints"] = {{"count", joints.size()}, {"max_error_before", js.max_error_before},
                        {"max_error_after", js.max_error_after}, {"correction_norm", js.correction_norm},
                        {"rank", js.rank}, {"exact", js.exact}};
  }
  const ffd::Deformer deformer(lattice);
  const auto t0 = Clock::now();
  nlohmann::json per_object = nlohmann::json::array();
  std::vector<std::string> bytes(objects.size());
  for (std::size_t oi = 0; oi < objects.size(); ++oi) {
    Object& ob = objects[oi];
    const std::vector<Eigen::Vector3d> rest = points_of(ob.mesh);
    for (const Eigen::Vector3d& p : rest)
      if (!p.allFinite()) throw bad_input("object '{}' has a non-finite coordinate ({})", ob.name, ob.path);
    nlohmann::json r = {{"name", ob.name}, {"mode", ob.mode}, {"vertices", rest.size()}};
    if (ob.mode != "ignore") {
      std::vector<Eigen::Vector3d> moved = rest;
      ffd::apply_all(deformer, moved, outside, threads);
      std::size_t changed = 0;
      for (std::size_t i = 0; i < rest.size(); ++i) changed += moved[i] != rest[i];
      r["vertices_moved"] = changed;
      if (ob.mode == "rigid") {
        // Area weights (docs/ffd.md 2.4); a point set without faces weighs its points equally.
        std::vector<double> area = vertex_areas(ob.mesh);
        double total = 0;
        for (const double a : area) total += a;
        if (!(total > 0)) area.clear();
        const ffd::RigidFit fit = ffd::fit_rigid(rest, moved, area);
        for (std::size_t i = 0; i < rest.size(); ++i) moved[i] = fit.rotation * rest[i] + fit.translation;
        r["rigid_rms"] = fit.rms;
      } else {
        double jmin = std::numeric_limits<double>::infinity(), jmax = -jmin;
        for (const Eigen::Vector3d& p : rest) {
          const double dj = deformer.jacobian(p, outside).determinant();
          jmin = std::min(jmin, dj);
          jmax = std::max(jmax, dj);
        }
        r["det_j"] = {{"min", jmin}, {"max", jmax}};
        // Faces that straddle the box boundary get stretched when a boundary point moves.
        std::size_t straddling = 0;
        for (const auto f : ob.mesh.faces()) {
          int in = 0, all = 0;
          for (const auto v : ob.mesh.fv_range(f)) {
            ++all;
            in += ffd::Deformer::inside(deformer.local(rest[static_cast<std::size_t>(v.idx())]));
          }
          straddling += in > 0 && in < all;
        }
        r["straddling_faces"] = straddling;
      }
      set_points(ob.mesh, moved);
      update_normals(ob.mesh, o.normals, ob.mode == "deform" ? &deformer : nullptr, rest, outside);
    }
    const formats::OutputFormat f = output_format(o.to, object_output(o.output, ob.name, objects.size()), ob.format);
    formats::MeshWriteOptions w;
    w.ascii = o.ascii;
    bytes[oi] = formats::write_mesh(ob.mesh, f.format, w);
    per_object.push_back(r);
  }
  report["objects"] = per_object;
  report["ms"] = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  for (std::size_t oi = 0; oi < objects.size(); ++oi) {
    const std::string path = object_output(o.output, objects[oi].name, objects.size());
    formats::store_output(path, bytes[oi], output_format(o.to, path, objects[oi].format).gzip);
  }
  if (!o.report.empty()) write_output(o.report, report.dump(2) + "\n");
  return 0;
}

int run_jacobian(const JacobianOptions& o) {
  const Lattice lattice = load_lattice(o.lattice);
  const ffd::Outside outside = outside_of(o.outside);
  const ffd::Deformer d(lattice);
  const Mesh m = load_mesh(o.input);
  std::string out = "vertex\tdetJ\n";
  for (const Eigen::Vector3d& p : points_of(m)) {
    if (!p.allFinite()) throw bad_input("the mesh has a non-finite coordinate ({})", o.input);
  }
  std::size_t i = 0;
  for (const Eigen::Vector3d& p : points_of(m)) out += fmt::format("{}\t{}\n", i++, d.jacobian(p, outside).determinant());
  write_output(o.output, out);
  return 0;
}

int run_lattice_mesh(const LatticeMeshOptions& o) {
  const Lattice l = load_lattice(o.input);
  const ffd::Deformer d(l);
  const Lattice& full = d.lattice();
  std::string out = fmt::format("# ffd control net {}x{}x{} ({})\n", l.dims[0], l.dims[1], l.dims[2], ffd::basis_name(l.basis[0]));
  for (int k = 0; k < l.dims[2]; ++k)
    for (int j = 0; j < l.dims[1]; ++j)
      for (int i = 0; i < l.dims[0]; ++i) {
        const Eigen::Vector3d p = full.rest_point(i, j, k) + full.displacement[full.index(i, j, k)];
        out += fmt::format("v {} {} {}\n", p[0], p[1], p[2]);
      }
  for (int k = 0; k < l.dims[2]; ++k)
    for (int j = 0; j < l.dims[1]; ++j)
      for (int i = 0; i < l.dims[0]; ++i) {
        const std::size_t n = full.index(i, j, k) + 1;
        if (i + 1 < l.dims[0]) out += fmt::format("l {} {}\n", n, full.index(i + 1, j, k) + 1);
        if (j + 1 < l.dims[1]) out += fmt::format("l {} {}\n", n, full.index(i, j + 1, k) + 1);
        if (k + 1 < l.dims[2]) out += fmt::format("l {} {}\n", n, full.index(i, j, k + 1) + 1);
      }
  write_output(o.output, out);
  return 0;
}

int run_convert(const ConvertOptions& o) {
  const Lattice l = load_lattice(o.input);
  if (o.to == "json") write_output(o.output, ffd::encode_lattice_json(l));
  else if (o.to == "pygem") write_output(o.output, ffd::encode_pygem_prm(l));
  else throw usage_error("--to: unknown '{}' (json, pygem)", o.to);
  return 0;
}

int run_animate(const AnimateOptions& o) {
  if (!(o.fps > 0 && o.fps <= 1000)) throw usage_error("--fps {} is outside (0, 1000]", o.fps);
  frame_name(o.output, 0);  // validates the pattern
  const int threads = resolve_threads(o.threads);
  const ffd::Outside outside = outside_of(o.outside);
  // Keys: "time lattice_file" rows, times strictly increasing; all lattices share the box.
  std::vector<std::pair<double, Lattice>> keys;
  {
    std::istringstream in(read_input(o.keys));
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line)) {
      ++n;
      std::istringstream row(line);
      std::string t, file;
      if (!(row >> t) || t[0] == '#' || t == "time") continue;
      double time = 0;
      try {
        time = std::stod(t);
      } catch (const std::exception&) {
        throw bad_input("keys line {}: '{}' is not a time ({})", n, t, o.keys);
      }
      if (!(row >> file)) throw bad_input("keys line {}: expected 'time lattice_file' ({})", n, o.keys);
      if (!keys.empty() && !(time > keys.back().first)) throw bad_input("keys line {}: times must increase ({})", n, o.keys);
      Lattice l = load_lattice(file);
      const ffd::Deformer d(l);
      l = d.lattice();
      if (!keys.empty()) {
        const Lattice& f = keys.front().second;
        if (l.dims != f.dims || l.basis != f.basis || !l.origin.isApprox(f.origin, 0) || l.axes != f.axes)
          throw bad_input("keys line {}: lattice box, dims or basis differ from the first key ({})", n, file);
      }
      keys.emplace_back(time, l);
    }
  }
  if (keys.empty()) throw bad_input("no key lattices ({})", o.keys);
  formats::Format format;
  Mesh mesh = load_mesh(o.input, &format);
  const std::vector<Eigen::Vector3d> rest = points_of(mesh);
  const double t0 = keys.front().first, duration = keys.back().first - t0;
  const long frames = static_cast<long>(std::floor(duration * o.fps + 1e-9)) + 1;
  std::string manifest = "frame\ttime\tfile\n";
  std::size_t seg = 0;
  for (long f = 0; f < frames; ++f) {
    const double t = t0 + static_cast<double>(f) / o.fps;
    while (seg + 1 < keys.size() && t > keys[seg + 1].first) ++seg;
    Lattice l = keys[seg].second;
    if (seg + 1 < keys.size()) {
      // Linear interpolation of displacements between the bracketing keys.
      const double a = (t - keys[seg].first) / (keys[seg + 1].first - keys[seg].first);
      if (a > 0)
        for (std::size_t i = 0; i < l.displacement.size(); ++i)
          l.displacement[i] = (1 - a) * keys[seg].second.displacement[i] + a * keys[seg + 1].second.displacement[i];
    }
    const ffd::Deformer d(l);
    std::vector<Eigen::Vector3d> p = rest;  // every frame from the rest mesh
    ffd::apply_all(d, p, outside, threads);
    set_points(mesh, p);
    update_normals(mesh, "recompute", nullptr, rest, outside);
    const std::string name = frame_name(o.output, f);
    const formats::OutputFormat of = output_format("", name, format);
    formats::store_output(name, formats::write_mesh(mesh, of.format), of.gzip);
    manifest += fmt::format("{}\t{}\t{}\n", f, t, name);
  }
  write_output(o.manifest, manifest);
  return 0;
}

}  // namespace fest::ffd_tool

#include "commands.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "ffd/joints.hpp"
#include "ffd/lattice.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

#include "mesh_lattice_io.hpp"

namespace fest::ffd_tool {

const char* object_mode_name(ObjectMode m) {
  switch (m) {
    case ObjectMode::rigid: return "rigid";
    case ObjectMode::ignore: return "ignore";
    case ObjectMode::deform: break;
  }
  return "deform";
}

int run_apply(const ApplyOptions& o) {
  const int threads = resolve_threads(o.threads);
  const ffd::Outside outside = o.outside;
  Lattice lattice = load_lattice(o.lattice);
  check_size(lattice, o.allow_large);

  // Objects: --in NAME=FILE, else the one mesh on -/input.
  struct Object {
    std::string name, path;
    ObjectMode mode = ObjectMode::deform;
    Mesh mesh;
    formats::Format format = formats::Format::ply;
  };
  std::vector<Object> objects;
  for (const NamedInput& in : o.inputs) objects.push_back({in.name, in.path, ObjectMode::deform, {}, formats::Format::ply});
  if (objects.empty()) objects.push_back({"mesh", o.input, ObjectMode::deform, {}, formats::Format::ply});
  for (const ObjectRole& role : o.objects) {
    auto it = std::find_if(objects.begin(), objects.end(), [&](const Object& x) { return x.name == role.name; });
    if (it == objects.end()) throw usage_error("--object: no object named '{}'", role.name);
    it->mode = role.mode;
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
  const Stopwatch watch;
  nlohmann::json per_object = nlohmann::json::array();
  std::vector<std::string> bytes(objects.size());
  for (std::size_t oi = 0; oi < objects.size(); ++oi) {
    Object& ob = objects[oi];
    const std::vector<Eigen::Vector3d> rest = points_of(ob.mesh);
    for (const Eigen::Vector3d& p : rest)
      if (!p.allFinite()) throw bad_input("object '{}' has a non-finite coordinate ({})", ob.name, ob.path);
    nlohmann::json r = {{"name", ob.name}, {"mode", object_mode_name(ob.mode)}, {"vertices", rest.size()}};
    if (ob.mode != ObjectMode::ignore) {
      std::vector<Eigen::Vector3d> moved = rest;
      ffd::apply_all(deformer, moved, outside, threads);
      std::size_t changed = 0;
      for (std::size_t i = 0; i < rest.size(); ++i) changed += moved[i] != rest[i];
      r["vertices_moved"] = changed;
      if (ob.mode == ObjectMode::rigid) {
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
      update_normals(ob.mesh, o.normals, ob.mode == ObjectMode::deform ? &deformer : nullptr, rest, outside);
    }
    const formats::OutputFormat f = output_format(o.to, object_output(o.output, ob.name, objects.size()), ob.format);
    formats::MeshWriteOptions w;
    w.ascii = o.ascii;
    bytes[oi] = formats::write_mesh(ob.mesh, f.format, w);
    per_object.push_back(r);
  }
  report["objects"] = per_object;
  report["ms"] = watch.ms();
  for (std::size_t oi = 0; oi < objects.size(); ++oi) {
    const std::string path = object_output(o.output, objects[oi].name, objects.size());
    formats::store_output(path, bytes[oi], output_format(o.to, path, objects[oi].format).gzip);
  }
  if (!o.report.empty()) write_output(o.report, report.dump(2) + "\n");
  return 0;
}

}  // namespace fest::ffd_tool

// softobj polygonize: skeleton -> closed mesh of f = V* (docs/softobj.md §3).
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "marching_cubes.hpp"
#include "mesh_output.hpp"
#include "skeleton_input.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/shrinkwrap.hpp"

namespace fest::softobj_tool {

int run_polygonize(const PolygonizeArgs& a) {
  const Stopwatch watch;
  if (a.iso != 0 && a.radius != 0) throw usage_error("--iso and --radius exclude each other");
  if (a.iso < 0 || (a.iso == 0 && a.radius < 0)) throw usage_error("--iso/--radius must be positive");
  softobj::Kernel kernel;
  if (a.kernel.wyvill) {
    kernel.kind = softobj::Kernel::wyvill;
    kernel.radius = a.kernel.radius;
    if (a.method != PolygonizeMethod::mc) throw usage_error("--kernel wyvill has no far field for shrink-wrap: use --method mc");
    if (a.iso == 0) throw usage_error("--kernel wyvill needs --iso (0 < iso < charge)");
  }
  const MeshTarget target = mesh_target(a.output, a.to);  // usage errors before any work
  const softobj::Skeleton s = read_skeleton(a.input, a.skeleton_format);
  const softobj::CompiledSkeleton compiled = softobj::compile_terms(s);
  const double iso = a.iso > 0 ? a.iso : a.radius > 0 ? s.charge / a.radius : s.iso > 0 ? s.iso : s.charge;
  // The offset radius: p / V* for Coulomb; for Wyvill the grid margin is R.
  const double rho = kernel.kind == softobj::Kernel::wyvill ? kernel.radius : s.charge / iso;
  const double lmax = a.lmax > 0 ? a.lmax : rho;
  const softobj::Field field(compiled, kernel);
  softobj::ShrinkwrapStats stats;
  TriMesh mesh;
  std::size_t dropped = 0;
  if (a.method == PolygonizeMethod::mc) {
    mesh = marching_cubes(field, iso, rho, a.grid > 0 ? a.grid : lmax / 2, static_cast<std::size_t>(a.max_verts),
                          &dropped);
    if (dropped)
      throw runtime_failure("marching cubes made {} non-manifold triangles the mesh cannot hold; try another --grid",
                            dropped);
  } else {
    softobj::ShrinkwrapOptions o;
    o.iso = iso;
    o.alpha_deg = a.alpha_deg;
    o.lmax = lmax;
    o.max_deviation = a.max_deviation;
    o.steps = a.steps;
    o.start_level = a.start_level;
    o.relax = a.relax;
    o.coarsen = !a.no_coarsen;
    o.max_vertices = static_cast<std::size_t>(a.max_verts);
    try {
      mesh = softobj::shrinkwrap(field, o, &stats);
    } catch (const Error& e) {
      if (e.status() != Status::failure) throw;
      throw Error(e.status(), std::string(e.what()) + "; use --method mc");
    }
  }
  const softobj::MeshMeasures m = softobj::measure(mesh);
  write_trimesh(mesh, target);
  if (!a.report.empty()) {
    nlohmann::json r;
    r["method"] = a.method == PolygonizeMethod::mc ? "mc" : "shrinkwrap";
    r["vertices"] = m.vertices;
    r["triangles"] = m.triangles;
    r["iso"] = iso;
    r["rho"] = rho;
    r["alpha_deg"] = a.alpha_deg;
    r["lmax"] = lmax;
    r["steps"] = a.steps;
    r["splits"] = stats.splits;
    r["collapses"] = stats.collapses;
    r["max_abs_f_err_rel"] = softobj::max_iso_error(field, mesh, iso);
    r["max_centroid_deviation"] = softobj::max_centroid_deviation(field, mesh, iso);
    r["max_sampled_deviation"] = softobj::max_sampled_deviation(field, mesh, iso);
    r["max_deviation_tolerance"] = a.max_deviation;
    r["min_angle_deg"] = m.min_angle_deg;
    r["max_edge"] = m.max_edge;
    r["max_normal_angle_deg"] = m.max_normal_angle_deg;
    r["volume"] = m.volume;
    r["area"] = m.area;
    r["euler_characteristic"] = m.euler_characteristic;
    r["closed"] = m.closed;
    r["skeleton_euler_characteristic"] = compiled.euler_characteristic;
    r["time_s"] = watch.seconds();
    write_output(a.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::softobj_tool

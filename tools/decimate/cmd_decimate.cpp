#include "commands.hpp"

#include <nlohmann/json.hpp>

#include "compare/mesh_compare.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "decimate/simplify.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::decimate_tool {

namespace {

decimate::SimplifyOptions simplify_options(const Options& o, const Mesh& mesh) {
  decimate::SimplifyOptions s;
  const std::size_t faces = mesh.n_faces();
  int targets = (o.faces > 0) + (o.ratio > 0);
  if (targets > 1) throw usage_error("give at most one of --faces and --ratio");
  if (o.ratio < 0 || o.ratio > 1) throw usage_error("--ratio {} is outside (0, 1]", o.ratio);
  if (o.error >= 0 && o.error_rel >= 0) throw usage_error("give at most one of --error and --error-rel");
  if (o.faces > 0) s.target_faces = o.faces;
  if (o.ratio > 0) s.target_faces = std::max<std::size_t>(1, static_cast<std::size_t>(o.ratio * static_cast<double>(faces)));
  if (o.error >= 0) s.max_error = o.error;
  if (o.error_rel >= 0) {
    OpenMesh::Vec3d lo(1e300), hi(-1e300);
    for (const auto v : mesh.vertices()) { lo.minimize(mesh.point(v)); hi.maximize(mesh.point(v)); }
    s.max_error = o.error_rel * (mesh.n_vertices() ? (hi - lo).norm() : 0.0);
  }
  if (s.target_faces == 0 && s.max_error < 0) throw usage_error("nothing to stop at: give --faces, --ratio, --error or --error-rel");
  s.lock_boundary = o.lock_boundary;
  s.lock_features = o.lock_features;
  if (!(o.feature_angle > 0 && o.feature_angle <= 180)) throw usage_error("--feature-angle {} is outside (0, 180]", o.feature_angle);
  s.feature_angle_deg = o.feature_angle;
  if (s.lock_features && o.feature_angle >= 180) throw usage_error("--lock features needs --feature-angle below 180");
  s.use_normals = s.use_colors = s.use_texcoords = !o.no_attributes;
  if (!(o.attribute_weight >= 0)) throw usage_error("--attribute-weight must be >= 0");
  s.attribute_weight = o.attribute_weight;
  s.optimal_placement = o.optimal_placement;
  s.weighting = o.weighting;
  return s;
}

}  // namespace

int run(const Options& o) {
  const int threads = resolve_threads(o.threads);
  formats::OutputFormat out_format{formats::Format::ply, false};
  bool out_known = false;
  if (!o.to.empty()) { out_format = formats::output_format_from_name(o.to); out_known = true; }
  else if (!is_stdio(o.output)) { out_format = formats::output_format_from_path(o.output); out_known = true; }
  if (out_known && formats::kind_of(out_format.format) != formats::Kind::mesh)
    throw usage_error("output format {} is not a mesh format", formats::format_name(out_format.format));

  const formats::Input in = formats::load_input(o.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("{} input is not a mesh ({})", formats::format_name(in.format), in.name);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  if (!out_known) out_format.format = in.format;
  if (mesh.n_faces() == 0) throw bad_input("the mesh has no faces ({})", in.name);
  const std::size_t skipped = formats::skipped_faces(mesh);
  if (skipped > 0 && !o.drop_nonmanifold)
    throw bad_input("{} non-manifold or degenerate faces cannot be simplified; --drop-nonmanifold drops them ({})", skipped,
                    in.name);
  if (skipped > 0 && !o.quiet) warn("decimate", fmt::format("dropped {} non-manifold or degenerate faces", skipped));
  decimate::SimplifyOptions s = simplify_options(o, mesh);
  Progress bar("decimate", 0, progress_wanted(o.progress));
  s.progress = bar.callback();

  decimate::SimplifyStats st;
  const Stopwatch watch;
  Mesh out = decimate::simplify(mesh, s, &st);
  bar.finish();
  const double ms = watch.ms();
  if (st.triangulated_polygons > 0 && !o.quiet)
    warn("decimate", fmt::format("{} polygons were split into triangles", st.triangulated_polygons));
  if (s.target_faces > 0 && !st.reached_target && s.max_error < 0 && !o.quiet)
    warn("decimate", fmt::format("stopped at {} faces: no further collapse keeps the surface manifold and unflipped "
                                 "(target {})", st.output_faces, s.target_faces));

  formats::MeshWriteOptions w;
  w.ascii = o.ascii;
  const std::string bytes = formats::write_mesh(out, out_format.format, w);

  if (!o.report.empty()) {
    const compare::SurfaceDistance d = compare::surface_distance(mesh, out, o.samples, 1, threads);
    nlohmann::json r;
    r["input"] = in.name;
    r["input_faces"] = st.input_faces;
    r["input_vertices"] = st.input_vertices;
    r["faces"] = st.output_faces;
    r["vertices"] = st.output_vertices;
    r["target_faces"] = s.target_faces;
    r["max_error_bound"] = s.max_error;
    r["reached_target"] = st.reached_target;
    r["collapses"] = st.collapses;
    r["rejected"] = {{"link", st.rejected_link}, {"flip", st.rejected_flip}, {"locked", st.rejected_locked}};
    r["boundary_edges"] = st.boundary_edges;
    r["feature_edges"] = st.feature_edges;
    r["locked_vertices"] = st.locked_vertices;
    r["quadric_dimension"] = st.dimension;
    r["max_error_estimate"] = st.max_error_estimate;
    r["hausdorff"] = d.hausdorff;
    r["rms"] = d.rms;
    r["mean"] = d.mean;
    r["max_input_to_output"] = d.max_a_to_b;
    r["max_output_to_input"] = d.max_b_to_a;
    r["ms"] = ms;
    write_output(o.report, r.dump(2) + "\n");
  }
  formats::store_output(o.output, bytes, out_format.gzip);
  return 0;
}

}  // namespace fest::decimate_tool

// isosurf: isosurfaces of volumes by loop-construction marching cubes over a min-max
// pyramid (docs/isosurf.md). Flags only; the subcommands live in cmd_*.cpp.

#include <cstring>
#include <vector>

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::isosurf;
  CLI::App app{"Isosurfaces of scalar volumes: exact marching cubes (asymptotic decider, watertight,\n"
               "deterministic) accelerated by a min-max pyramid, and mesh statistics.",
               "isosurf"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error. See isosurf(1).");

  ExactOptions ex;
  auto* e = app.add_subcommand("exact", "Full-resolution surface f = iso (the default subcommand); mesh to standard output or -o");
  e->fallthrough();
  e->add_option("input", ex.input, "Volume: NIfTI, NRRD, MHA, VTI or a fest frame stream (- = stdin)");
  e->add_option("-o,--output", ex.output, "Mesh output (- = stdout; format from the extension)");
  e->add_option("--to", ex.to, "Mesh format: ply (binary), plya (ascii PLY), obj, off, stl, drc");
  e->add_option("--iso", ex.iso, "Iso-value; inside is f >= iso (use half-integers on integer data)");
  e->add_option("--label", ex.labels, "Surface of the union of these labels K[,K...] (iso 0.5 of the indicator)");
  e->add_option("--field", ex.field, "VTI point array or frame-stream field");
  e->add_option("--component", ex.component, "Vector fields: mag, x, y or z")->check(CLI::IsMember({"mag", "x", "y", "z"}));
  e->add_option("--frame", ex.frame, "Frame of a frame stream (0-based; default the last)")->check(CLI::NonNegativeNumber);
  auto* cap = e->add_option("--cap", ex.cap_value, "Pad by one layer of VALUE (default min(f)-1) so boundary-cut surfaces close")
                  ->expected(0, 1);
  e->add_option("--face-rule", ex.face_rule, "Ambiguous faces: decider (asymptotic decider) or separate")
      ->check(CLI::IsMember({"decider", "separate"}));
  e->add_option("--tri", ex.tri, "Loop triangulation: minarea, fan or centroid")->check(CLI::IsMember({"minarea", "fan", "centroid"}));
  e->add_option("--component-filter", ex.component_filter, "Keep all components, the largest, or the N largest");
  e->add_flag("--index-space", ex.index_space, "Vertices in voxel coordinates instead of world units");
  e->add_option("--smooth", ex.smooth, "Taubin lambda|mu smoothing iterations (0.5 / -0.53; boundary fixed)")->check(CLI::Range(0, 100000));
  e->add_option("--roi", ex.roi, "Only the samples i0..i1, j0..j1, k0..k1 (inclusive): i0,i1,j0,j1,k0,k1");
  e->add_flag("--normals", ex.normals, "Per-vertex normals from the interpolated gradient (-grad f); ply, plya, obj, off or drc");
  e->add_flag("--nan-outside", ex.nan_outside, "Treat NaN samples as outside instead of refusing the input");
  e->add_flag("--no-octree", ex.no_octree, "Scan every cell (same output; for comparisons)");
  e->add_option("--qbits", ex.qbits, "Draco position quantization bits (0 = lossless)")->check(CLI::Range(0, 30));
  e->add_option("--report", ex.report, "Write counts, topology, area, volume and timings as JSON");
  fest::cli::add_threads(*e, ex.threads);

  ExactOptions ad_ex;
  AdaptiveArgs ad;
  auto* d = app.add_subcommand("adaptive", "Focus-adaptive crack-free surface: coarser octree leaves far from --focus and where the data is smooth");
  d->fallthrough();
  d->add_option("input", ad_ex.input, "Volume (- = stdin)");
  d->add_option("-o,--output", ad_ex.output, "Mesh output (- = stdout)");
  d->add_option("--to", ad_ex.to, "Mesh format: ply, plya, obj, off, stl, drc");
  d->add_option("--iso", ad_ex.iso, "Iso-value");
  d->add_option("--label", ad_ex.labels, "Surface of the union of these labels");
  d->add_option("--field", ad_ex.field, "VTI point array or frame-stream field");
  d->add_option("--component", ad_ex.component, "Vector fields: mag, x, y or z")->check(CLI::IsMember({"mag", "x", "y", "z"}));
  d->add_option("--frame", ad_ex.frame, "Frame of a frame stream")->check(CLI::NonNegativeNumber);
  auto* dcap = d->add_option("--cap", ad_ex.cap_value, "Pad by one layer of VALUE (default min(f)-1)")->expected(0, 1);
  d->add_option("--face-rule", ad_ex.face_rule, "decider or separate")->check(CLI::IsMember({"decider", "separate"}));
  d->add_option("--tri", ad_ex.tri, "minarea, fan or centroid")->check(CLI::IsMember({"minarea", "fan", "centroid"}));
  d->add_option("--component-filter", ad_ex.component_filter, "all, largest or N");
  d->add_flag("--index-space", ad_ex.index_space, "Vertices in voxel coordinates");
  d->add_option("--smooth", ad_ex.smooth, "Taubin lambda|mu smoothing iterations (0.5 / -0.53; boundary fixed)")->check(CLI::Range(0, 100000));
  d->add_option("--roi", ad_ex.roi, "Only the samples i0..i1, j0..j1, k0..k1 (inclusive): i0,i1,j0,j1,k0,k1");
  d->add_flag("--normals", ad_ex.normals, "Per-vertex normals from the interpolated gradient (-grad f); ply, plya, obj, off or drc");
  d->add_flag("--nan-outside", ad_ex.nan_outside, "Treat NaN samples as outside");
  d->add_option("--qbits", ad_ex.qbits, "Draco quantization bits")->check(CLI::Range(0, 30));
  d->add_option("--report", ad_ex.report, "JSON report (with leaves per level)");
  d->add_option("--focus", ad.focus, "Focus point X,Y,Z (world units)");
  d->add_option("--focus-radius", ad.focus_radius, "Full resolution within r0 of the focus; one level coarser per doubling (default diagonal/32)");
  d->add_option("--max-error", ad.max_error, "Tolerated trilinear error eps0 (data units), or inf (distance rule only)");
  d->add_option("--error-growth", ad.error_growth, "eps = eps0 (1 + d/r0)^P")->check(CLI::Range(0.0, 16.0));
  d->add_option("--max-level", ad.max_level, "Coarsest leaf level")->check(CLI::Range(0, 30));
  d->add_option("--edge-rule", ad.edge_rule, "Leaf edges with one finest crossing at most: transitions (default) or all (keeps thin features)")
      ->check(CLI::IsMember({"transitions", "all"}));
  fest::cli::add_threads(*d, ad_ex.threads);

  ExactOptions pr_ex;
  AdaptiveArgs pr_ad;
  ProgressiveArgs pr;
  auto* g = app.add_subcommand("progressive", "Crack-free meshes coarse to fine (--errors E0,...,0) or per focus position (--focus-path) into -o DIR");
  g->fallthrough();
  g->add_option("input", pr_ex.input, "Volume (- = stdin)");
  g->add_option("-o,--output", pr_ex.output, "Output directory (level_NN.* or frame_NN.*, manifest.json)");
  g->add_option("--to", pr_ex.to, "Mesh format: ply, plya, obj, off, stl, drc");
  g->add_option("--iso", pr_ex.iso, "Iso-value");
  g->add_option("--label", pr_ex.labels, "Surface of the union of these labels");
  g->add_option("--field", pr_ex.field, "VTI point array or frame-stream field");
  g->add_option("--frame", pr_ex.frame, "Frame of a frame stream")->check(CLI::NonNegativeNumber);
  auto* gcap = g->add_option("--cap", pr_ex.cap_value, "Pad by one layer of VALUE (default min(f)-1)")->expected(0, 1);
  g->add_option("--face-rule", pr_ex.face_rule, "decider or separate")->check(CLI::IsMember({"decider", "separate"}));
  g->add_option("--tri", pr_ex.tri, "minarea, fan or centroid")->check(CLI::IsMember({"minarea", "fan", "centroid"}));
  g->add_option("--qbits", pr_ex.qbits, "Draco quantization bits")->check(CLI::Range(0, 30));
  g->add_option("--errors", pr.errors, "Tolerances E0,E1,...,0, descending (coarse first); 0 = the exact surface");
  g->add_option("--focus-path", pr.focus_path, "CSV of focus positions x,y,z: one adaptive mesh per row");
  g->add_option("--focus", pr_ad.focus, "Focus point X,Y,Z for --errors");
  g->add_option("--focus-radius", pr_ad.focus_radius, "r0 (default diagonal/32)");
  g->add_option("--error-growth", pr_ad.error_growth, "eps = eps0 (1 + d/r0)^P")->check(CLI::Range(0.0, 16.0));
  g->add_option("--max-level", pr_ad.max_level, "Coarsest leaf level")->check(CLI::Range(0, 30));
  g->add_option("--edge-rule", pr_ad.edge_rule, "Leaf edges with one finest crossing at most: transitions (default) or all")
      ->check(CLI::IsMember({"transitions", "all"}));
  fest::cli::add_threads(*g, pr_ex.threads);

  StatsOptions st;
  auto* s = app.add_subcommand("stats", "Topology (boundary/non-manifold edges, components, Euler, genus), area and volume of a mesh as JSON");
  s->add_option("mesh", st.input, "Mesh: PLY, OBJ, OFF, STL, Draco (- = stdin)");
  s->add_option("--report", st.report, "Also write the JSON to this file");

  // `isosurf IN --iso V` means `isosurf exact IN --iso V` (spec §4).
  std::vector<char*> args(argv, argv + argc);
  bool named = false, meta = false;
  for (int i = 1; i < argc; ++i) {
    for (const char* sub : {"exact", "adaptive", "progressive", "stats"}) named = named || std::strcmp(argv[i], sub) == 0;
    for (const char* m : {"-h", "--help", "--version"}) meta = meta || std::strcmp(argv[i], m) == 0;
  }
  static char exact_word[] = "exact";
  if (!named && !meta && argc > 1) args.insert(args.begin() + 1, exact_word);

  return fest::cli::run(app, static_cast<int>(args.size()), args.data(), [&]() -> int {
    if (*e) {
      ex.cap = cap->count() > 0;
      ex.quiet = common.quiet;
      return run_exact(ex);
    }
    if (*d) {
      ad_ex.cap = dcap->count() > 0;
      ad_ex.quiet = common.quiet;
      return run_adaptive(ad_ex, ad);
    }
    if (*g) {
      pr_ex.cap = gcap->count() > 0;
      return run_progressive(pr_ex, pr_ad, pr);
    }
    if (*s) return run_stats(st);
    return 2;
  });
}

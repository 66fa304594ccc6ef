// isosurf: isosurfaces of volumes by loop-construction marching cubes over a min-max
// pyramid (docs/isosurf.md). Flags only; the subcommands live in cmd_*.cpp.

#include <climits>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/number_list.hpp"
#include "commands.hpp"

namespace {

using namespace fest::isosurf_tool;
using fest::isosurface::EdgeRule;
using fest::isosurface::FaceRule;
using fest::isosurface::Triangulation;

// Flags whose text becomes typed options once CLI11 has parsed (lib/cli parsers).
struct ListFlags {
  std::string labels, roi, component_filter = "all", focus, max_error = "0", raw, raw_spacing;
  std::vector<std::string> errors;
};

CLI::Option* face_rule(CLI::App* s, ExactOptions& o, const char* help) {
  return fest::cli::enum_words<FaceRule>(s->add_option("--face-rule", o.face_rule, help),
                               {{"decider", FaceRule::decider}, {"separate", FaceRule::separate}});
}
CLI::Option* triangulation(CLI::App* s, ExactOptions& o, const char* help) {
  return fest::cli::enum_words<Triangulation>(s->add_option("--tri", o.tri, help),
                               {{"minarea", Triangulation::minarea}, {"fan", Triangulation::fan}, {"centroid", Triangulation::centroid}});
}
CLI::Option* edge_rule(CLI::App* s, AdaptiveArgs& a, const char* help) {
  return fest::cli::enum_words<EdgeRule>(s->add_option("--edge-rule", a.edge_rule, help),
                               {{"transitions", EdgeRule::transitions}, {"all", EdgeRule::all}});
}
void add_raw(CLI::App* s, ListFlags& t) {
  s->add_option("--raw", t.raw, "Headerless input: NX,NY,NZ,TYPE[,little|big] (TYPE uint8, int8, uint16, int16, uint32, "
                                "int32, uint64, int64, float32, float64; x fastest; little-endian by default)");
  s->add_option("--raw-spacing", t.raw_spacing, "Sample spacing SX,SY,SZ of --raw input (default 1,1,1)");
}

// --raw and --raw-spacing -> the layout (docs/isosurf.md "Inputs").
std::optional<fest::formats::RawLayout> raw_layout(const ListFlags& t) {
  if (t.raw.empty()) {
    if (!t.raw_spacing.empty()) throw fest::usage_error("--raw-spacing needs --raw");
    return std::nullopt;
  }
  fest::formats::RawLayout layout;
  try {
    layout = fest::formats::parse_raw_layout(t.raw);
  } catch (const std::invalid_argument& e) {
    throw fest::usage_error("--raw {}", e.what());
  }
  if (!t.raw_spacing.empty()) {
    const auto sp = fest::cli::number_list(t.raw_spacing, 3, 3, "--raw-spacing");
    for (int a = 0; a < 3; ++a) {
      if (!(sp[a] > 0)) throw fest::usage_error("--raw-spacing takes positive spacings, not '{}'", t.raw_spacing);
      layout.spacing[a] = sp[a];
    }
  }
  return layout;
}

// The list flags of exact/adaptive/progressive -> typed options.
void fill(ExactOptions& o, const ListFlags& t) {
  if (!t.labels.empty())
    for (long long k : fest::cli::integer_list(t.labels, 1, 0, "--label", LLONG_MIN / 2, LLONG_MAX / 2)) o.labels.push_back(k);
  if (!t.roi.empty()) {
    const auto r = fest::cli::integer_list(t.roi, 6, 6, "--roi", -(1LL << 40), 1LL << 40);
    o.roi = std::array<long long, 6>{r[0], r[1], r[2], r[3], r[4], r[5]};
  }
  if (t.component_filter == "largest") {
    o.keep_components = 1;
  } else if (t.component_filter != "all") {
    char* end = nullptr;
    const long n = std::strtol(t.component_filter.c_str(), &end, 10);
    if (t.component_filter.empty() || *end || n < 1) throw fest::usage_error("--component-filter must be all, largest or a count >= 1");
    o.keep_components = static_cast<std::size_t>(n);
  }
  o.raw = raw_layout(t);
}

double tolerance(const std::string& text, const char* flag) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  return fest::cli::number_list(text, 1, 1, flag)[0];
}

void fill(AdaptiveArgs& a, const ListFlags& t) {
  if (!t.focus.empty()) {
    const auto f = fest::cli::number_list(t.focus, 3, 3, "--focus");
    a.focus = std::array<double, 3>{f[0], f[1], f[2]};
  }
  a.max_error = tolerance(t.max_error, "--max-error");
}

// --component mag|x|y|z
void component(CLI::App* s, fest::formats::VectorComponent& c) {
  using fest::formats::VectorComponent;
  fest::cli::enum_words<VectorComponent>(s->add_option("--component", c, "Vector fields: mag, x, y or z"),
                                         {{"mag", VectorComponent::mag}, {"x", VectorComponent::x}, {"y", VectorComponent::y}, {"z", VectorComponent::z}});
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Isosurfaces of scalar volumes: exact marching cubes (asymptotic decider, watertight,\n"
               "deterministic) accelerated by a min-max pyramid, and mesh statistics.",
               "isosurf"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error. See isosurf(1).");

  ExactOptions ex;
  ListFlags ext;
  auto* e = app.add_subcommand("exact", "Full-resolution surface f = iso (the default subcommand); mesh to standard output or -o");
  e->fallthrough();
  e->add_option("input", ex.input, "Volume: NIfTI, NRRD, MHA, VTI or a fest frame stream (- = stdin)");
  e->add_option("-o,--output", ex.output, "Mesh output (- = stdout; format from the extension)");
  e->add_option("--to", ex.to, "Mesh format: ply (binary), plya (ascii PLY), obj, off, stl, drc");
  e->add_option("--iso", ex.iso, "Iso-value; inside is f >= iso (use half-integers on integer data)");
  e->add_option("--label", ext.labels, "Surface of the union of these labels K[,K...] (iso 0.5 of the indicator)");
  e->add_option("--field", ex.field, "VTI point array or frame-stream field");
  component(e, ex.component);
  e->add_option("--frame", ex.frame, "Frame of a frame stream or 4-D series (0-based; default the last)")->check(fest::cli::non_negative);
  auto* cap = e->add_option("--cap", ex.cap_value, "Pad by one layer of VALUE (default min(f)-1) so boundary-cut surfaces close")
                  ->expected(0, 1);
  face_rule(e, ex, "Ambiguous faces: decider (asymptotic decider) or separate");
  triangulation(e, ex, "Loop triangulation: minarea, fan or centroid");
  e->add_option("--component-filter", ext.component_filter, "Keep all components, the largest, or the N largest");
  e->add_flag("--index-space", ex.index_space, "Vertices in voxel coordinates instead of world units");
  e->add_option("--smooth", ex.smooth, "Taubin lambda|mu smoothing iterations (0.5 / -0.53; boundary fixed)")->check(fest::cli::range(0, 100000));
  e->add_option("--roi", ext.roi, "Only the samples i0..i1, j0..j1, k0..k1 (inclusive): i0,i1,j0,j1,k0,k1");
  e->add_flag("--normals", ex.normals, "Per-vertex normals from the interpolated gradient (-grad f); ply, plya, obj, off or drc");
  e->add_flag("--nan-outside", ex.nan_outside, "Treat NaN samples as outside instead of refusing the input");
  e->add_flag("--no-octree", ex.no_octree, "Scan every cell (same output; for comparisons)");
  e->add_option("--qbits", ex.qbits, "Draco position quantization bits (0 = lossless)")->check(fest::cli::range(0, 30));
  e->add_option("--report", ex.report, "Write counts, topology, area, volume and timings as JSON");
  add_raw(e, ext);
  fest::cli::add_threads(*e, ex.threads);
  fest::cli::add_progress(*e, ex.progress);

  ExactOptions ad_ex;
  AdaptiveArgs ad;
  ListFlags adt;
  auto* d = app.add_subcommand("adaptive", "Focus-adaptive crack-free surface: coarser octree leaves far from --focus and where the data is smooth");
  d->fallthrough();
  d->add_option("input", ad_ex.input, "Volume (- = stdin)");
  d->add_option("-o,--output", ad_ex.output, "Mesh output (- = stdout)");
  d->add_option("--to", ad_ex.to, "Mesh format: ply, plya, obj, off, stl, drc");
  d->add_option("--iso", ad_ex.iso, "Iso-value");
  d->add_option("--label", adt.labels, "Surface of the union of these labels");
  d->add_option("--field", ad_ex.field, "VTI point array or frame-stream field");
  component(d, ad_ex.component);
  d->add_option("--frame", ad_ex.frame, "Frame of a frame stream or 4-D series")->check(fest::cli::non_negative);
  auto* dcap = d->add_option("--cap", ad_ex.cap_value, "Pad by one layer of VALUE (default min(f)-1)")->expected(0, 1);
  face_rule(d, ad_ex, "decider or separate");
  triangulation(d, ad_ex, "minarea, fan or centroid");
  d->add_option("--component-filter", adt.component_filter, "all, largest or N");
  d->add_flag("--index-space", ad_ex.index_space, "Vertices in voxel coordinates");
  d->add_option("--smooth", ad_ex.smooth, "Taubin lambda|mu smoothing iterations (0.5 / -0.53; boundary fixed)")->check(fest::cli::range(0, 100000));
  d->add_option("--roi", adt.roi, "Only the samples i0..i1, j0..j1, k0..k1 (inclusive): i0,i1,j0,j1,k0,k1");
  d->add_flag("--normals", ad_ex.normals, "Per-vertex normals from the interpolated gradient (-grad f); ply, plya, obj, off or drc");
  d->add_flag("--nan-outside", ad_ex.nan_outside, "Treat NaN samples as outside");
  d->add_option("--qbits", ad_ex.qbits, "Draco quantization bits")->check(fest::cli::range(0, 30));
  d->add_option("--report", ad_ex.report, "JSON report (with leaves per level)");
  d->add_option("--focus", adt.focus, "Focus point X,Y,Z (world units)");
  d->add_option("--focus-radius", ad.focus_radius, "Full resolution within r0 of the focus; one level coarser per doubling (default diagonal/32)");
  d->add_option("--max-error", adt.max_error, "Tolerated trilinear error eps0 (data units), or inf (distance rule only)");
  d->add_option("--error-growth", ad.error_growth, "eps = eps0 (1 + d/r0)^P")->check(fest::cli::range(0.0, 16.0));
  d->add_option("--max-level", ad.max_level, "Coarsest leaf level")->check(fest::cli::range(0, 30));
  edge_rule(d, ad, "Leaf edges with one finest crossing at most: transitions (default) or all (keeps thin features)");
  add_raw(d, adt);
  fest::cli::add_threads(*d, ad_ex.threads);
  fest::cli::add_progress(*d, ad_ex.progress);

  ExactOptions pr_ex;
  AdaptiveArgs pr_ad;
  ProgressiveArgs pr;
  ListFlags prt;
  auto* g = app.add_subcommand("progressive", "Crack-free meshes coarse to fine (--errors E0,...,0) or per focus position (--focus-path) into -o DIR");
  g->fallthrough();
  g->add_option("input", pr_ex.input, "Volume (- = stdin)");
  g->add_option("-o,--output", pr_ex.output, "Output directory (level_NN.* or frame_NN.*, manifest.json)");
  g->add_option("--to", pr_ex.to, "Mesh format: ply, plya, obj, off, stl, drc");
  g->add_option("--iso", pr_ex.iso, "Iso-value");
  g->add_option("--label", prt.labels, "Surface of the union of these labels");
  g->add_option("--field", pr_ex.field, "VTI point array or frame-stream field");
  g->add_option("--frame", pr_ex.frame, "Frame of a frame stream or 4-D series")->check(fest::cli::non_negative);
  auto* gcap = g->add_option("--cap", pr_ex.cap_value, "Pad by one layer of VALUE (default min(f)-1)")->expected(0, 1);
  face_rule(g, pr_ex, "decider or separate");
  triangulation(g, pr_ex, "minarea, fan or centroid");
  g->add_option("--qbits", pr_ex.qbits, "Draco quantization bits")->check(fest::cli::range(0, 30));
  g->add_option("--errors", prt.errors, "Tolerances E0,E1,...,0, descending (coarse first); 0 = the exact surface")->delimiter(',');
  g->add_option("--focus-path", pr.focus_path, "CSV of focus positions x,y,z: one adaptive mesh per row");
  g->add_option("--focus", prt.focus, "Focus point X,Y,Z for --errors");
  g->add_option("--focus-radius", pr_ad.focus_radius, "r0 (default diagonal/32)");
  g->add_option("--error-growth", pr_ad.error_growth, "eps = eps0 (1 + d/r0)^P")->check(fest::cli::range(0.0, 16.0));
  g->add_option("--max-level", pr_ad.max_level, "Coarsest leaf level")->check(fest::cli::range(0, 30));
  edge_rule(g, pr_ad, "Leaf edges with one finest crossing at most: transitions (default) or all");
  add_raw(g, prt);
  fest::cli::add_threads(*g, pr_ex.threads);
  fest::cli::add_progress(*g, pr_ex.progress);

  StatsOptions st;
  auto* s = app.add_subcommand("stats", "Topology (boundary/non-manifold edges, components, Euler, genus), area and volume of a mesh as JSON");
  s->add_option("mesh", st.input, "Mesh: PLY, OBJ, OFF, STL, Draco (- = stdin)");
  s->add_option("--report", st.report, "Also write the JSON to this file");

  // `isosurf IN --iso V` means `isosurf exact IN --iso V` (isosurf(1), SYNOPSIS: `exact` may be left out).
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
      fill(ex, ext);
      return run_exact(ex);
    }
    if (*d) {
      ad_ex.cap = dcap->count() > 0;
      ad_ex.quiet = common.quiet;
      fill(ad_ex, adt);
      fill(ad, adt);
      return run_adaptive(ad_ex, ad);
    }
    if (*g) {
      pr_ex.cap = gcap->count() > 0;
      fill(pr_ex, prt);
      fill(pr_ad, prt);
      for (const auto& item : prt.errors) pr.errors.push_back(tolerance(item, "--errors"));
      return run_progressive(pr_ex, pr_ad, pr);
    }
    if (*s) return run_stats(st);
    return 2;
  });
}

// softobj: soft objects from point, segment and triangle skeletons, polygonised by
// shrink-wrapping their equipotential surface; the tongue model (docs/softobj.md).
//
// Wiring only: this file maps flags onto commands.hpp.

#include <cmath>
#include <cstdlib>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

// --kernel coulomb | wyvill:R (R a positive number).
fest::softobj_tool::KernelChoice parse_kernel(const std::string& k) {
  if (k == "coulomb") return {};
  if (k.rfind("wyvill:", 0) != 0) throw fest::usage_error("--kernel {} is not coulomb or wyvill:R", k);
  char* end = nullptr;
  const double r = std::strtod(k.c_str() + 7, &end);
  if (*end != '\0' || !(r > 0) || !std::isfinite(r)) throw fest::usage_error("--kernel {}: R must be a positive number", k);
  return {true, r};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::softobj_tool;
  CLI::App app{"Soft objects: the equipotential surface of point, segment and triangle skeletons as a closed,\n"
               "curvature-adaptive mesh whose vertices lie on the surface (shrink-wrap); the tongue model.",
               "softobj"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  PolygonizeArgs pa;
  auto* poly = app.add_subcommand("polygonize", "Skeleton (JSON or mesh) -> closed mesh of f = V*");
  poly->add_option("input", pa.input, "Skeleton file, - = standard input");
  poly->add_option("-o,--output", pa.output, "Mesh file (.ply .obj .off .stl), - = standard output (binary PLY)");
  poly->add_option("--to", pa.to, "Output format: ply, plya (ascii PLY), obj, off, stl");
  auto* iso = poly->add_option("--iso", pa.iso, "Iso value V* (> 0)")->check(fest::cli::positive);
  poly->add_option("--radius", pa.radius, "Offset radius rho: V* = p / rho")->check(fest::cli::positive)->excludes(iso);
  poly->add_option("--alpha", pa.alpha_deg, "Largest angle between a chord's end normals, degrees")
      ->check(fest::cli::range(0.5, 90.0));
  poly->add_option("--lmax", pa.lmax, "Longest chord (default rho)")->check(fest::cli::positive);
  poly->add_option("--max-deviation", pa.max_deviation,
                   "Also split chords/triangles whose midpoint/centroid is farther than this from the surface")
      ->check(fest::cli::positive);
  poly->add_option("--steps", pa.steps, "Iso steps K from V_0 to V*")->check(fest::cli::range(1, 1000));
  poly->add_option("--start-level", pa.start_level, "Icosphere subdivision level of the start mesh")
      ->check(fest::cli::range(0, 5));
  poly->add_option("--relax", pa.relax, "Tangential relaxation lambda (0 = off)")->check(fest::cli::range(0.0, 1.0));
  poly->add_flag("--no-coarsen", pa.no_coarsen, "Do not collapse short flat chords");
  poly->add_option("--max-verts", pa.max_verts, "Vertex limit")->check(fest::cli::range(4LL, 100000000LL));
  fest::cli::enum_words<PolygonizeMethod>(
      poly->add_option("--method", pa.method, "shrinkwrap (adaptive, genus 0) or mc (marching cubes, any topology)"),
      {{"shrinkwrap", PolygonizeMethod::shrinkwrap}, {"mc", PolygonizeMethod::mc}});
  poly->add_option("--grid", pa.grid, "Marching-cubes grid spacing (default lmax/2)")->check(fest::cli::positive);
  poly->add_option_function<std::string>(
      "--kernel", [&pa](const std::string& k) { pa.kernel = parse_kernel(k); },
      "coulomb (p/d), or wyvill:R (compact; needs --method mc)");
  fest::cli::enum_words<SkeletonFormat>(
      poly->add_option("--skeleton-format", pa.skeleton_format, "json, or mesh: a mesh's triangles are the skeleton"),
      {{"json", SkeletonFormat::json}, {"mesh", SkeletonFormat::mesh}});
  poly->add_option("--report", pa.report, "JSON statistics: counts, errors, volume, area");

  TongueArgs ta;
  auto* tongue = app.add_subcommand("tongue", "Tongue shape parameters (TSV row) -> skeleton JSON");
  tongue->add_option("input", ta.input, "Parameter TSV (time x0 y0 z0 l1..l9 a1..a3 c1..c6), - = standard input");
  tongue->add_option("-o,--output", ta.output, "Skeleton JSON, - = standard output");
  tongue->add_flag("--neutral", ta.neutral, "Start from the neutral shape and read no input");
  tongue->add_option("--frame", ta.frame, "Row of the TSV (0 = first)")->check(fest::cli::non_negative);
  fest::cli::enum_words<TongueLayoutChoice>(tongue->add_option("--layout", ta.layout, "Triangles: default (10, symmetric disk) or paper9 (9)"),
                        {{"default", TongueLayoutChoice::default10}, {"paper9", TongueLayoutChoice::paper9}});
  tongue->add_option("--set", ta.set, "Override parameters: name=value[,name=value...]")->delimiter(',');
  tongue->add_option("--radius", ta.radius, "Offset radius rho in mm (iso = 1/rho)")->check(fest::cli::positive);

  tongue->add_flag("--polygonize", ta.polygonize,
                   "Every row: palate pass 1, shrink-wrap, pass 2; -o is a pattern (frames/t%04d.ply); "
                   "a TSV manifest on standard output");
  tongue->add_option("--alpha", ta.alpha_deg, "With --polygonize: largest chord normal angle, degrees")
      ->check(fest::cli::range(0.5, 90.0));
  tongue->add_option("--lmax", ta.lmax, "With --polygonize: longest chord (default rho)")->check(fest::cli::positive);
  tongue->add_option("--max-deviation", ta.max_deviation, "With --polygonize: deviation tolerance of the refinement")
      ->check(fest::cli::positive);
  tongue->add_option("--steps", ta.steps, "With --polygonize: iso steps")->check(fest::cli::range(1, 1000));
  fest::cli::add_threads(*tongue, ta.threads);
  fest::cli::add_progress(*tongue, ta.progress);
  tongue->add_option("--palate", ta.palate, "Palate JSON: keep the skeleton inside the virtual palate (pass 1)");

  PalateArgs pla;
  auto* palate = app.add_subcommand("palate", "Project mesh vertices outside the palate onto it (pass 2)");
  palate->add_option("input", pla.input, "Mesh, - = standard input");
  palate->add_option("--palate", pla.palate, "Palate JSON")->required();
  palate->add_option("-o,--output", pla.output, "Mesh file, - = standard output (binary PLY)");
  palate->add_option("--to", pla.to, "Output format: ply, plya, obj, off, stl");

  FieldArgs fa;
  auto* field = app.add_subcommand("field", "f and grad f of a skeleton at points (TSV/CSV with x y z)");
  field->add_option("input", fa.input, "Skeleton JSON, - = standard input");
  field->add_option("--at", fa.at, "Points table")->required();
  field->add_option("-o,--output", fa.output, "TSV x y z f gx gy gz, - = standard output");

  AnimateArgs aa;
  auto* animate = app.add_subcommand("animate", "Phoneme timeline -> tongue parameters per frame (coarticulation)");
  animate->add_option("input", aa.input, "Timeline: phoneme start_s end_s per line, - = standard input");
  animate->add_option("--table", aa.table, "Phoneme table JSON (targets, classes, speeds, lags)")->required();
  animate->add_option("--fps", aa.fps, "Frames per second")->check(fest::cli::range(0.1, 10000.0));
  animate->add_option("-o,--output", aa.output, "Parameter TSV, - = standard output");

  return fest::cli::run(app, argc, argv, [&] {
    if (*poly) return run_polygonize(pa);
    if (*tongue) return run_tongue(ta);
    if (*animate) return run_animate(aa);
    if (*palate) return run_palate(pla);
    return run_field(fa);
  });
}

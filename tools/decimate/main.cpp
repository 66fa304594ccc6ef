// decimate: simplify a triangle mesh by quadric-ordered edge collapses to a face count or
// an error bound (docs/decimate.md). Flags only; the work is in cmd_decimate.cpp.

#include <OpenMesh/Core/System/omstream.hh>

#include <sstream>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Simplify a triangle mesh to a face count or an error bound (Garland-Heckbert quadrics with attributes,\n"
               "manifold-safe edge collapses, boundary/feature constraints); Hausdorff and RMS error in --report.",
               "decimate"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  fest::decimate_tool::Options o;
  app.add_option("input", o.input, "Input mesh (PLY, OFF, OBJ, STL, Draco), or - for standard input")->default_val("-");
  app.add_option("-o,--output", o.output, "Output mesh, or - for standard output")->default_val("-");
  app.add_option("--to", o.to, "Output format (ply, off, obj, stl, drc); default: from -o, else the input's");
  app.add_option("--faces", o.faces, "Target face count")->check(fest::cli::range(1, 2147483647));
  app.add_option("--ratio", o.ratio, "Target face count as a fraction of the input's (0 < r <= 1)");
  app.add_option("--error", o.error, "Stop before a collapse whose error estimate exceeds this length");
  app.add_option("--error-rel", o.error_rel, "The same, as a fraction of the bounding-box diagonal");
  app.add_option_function<std::string>(
      "--lock",
      [&o](const std::string& list) {
        std::stringstream items(list);
        std::string item;
        while (std::getline(items, item, ',')) {
          if (item == "boundary") o.lock_boundary = true;
          else if (item == "features") o.lock_features = true;
          else if (!item.empty()) throw fest::usage_error("--lock: unknown '{}' (boundary, features)", item);
        }
      },
      "Vertices that never move: boundary, features (comma-separated)");
  app.add_option("--feature-angle", o.feature_angle, "Dihedral angle (degrees) above which an edge is a feature")
      ->default_val(180);
  app.add_flag("--no-attributes", o.no_attributes, "Quadrics over positions only (ignore normals, colours, texcoords)");
  app.add_option("--attribute-weight", o.attribute_weight, "Weight of attribute differences (in bbox diagonals)")
      ->default_val(1.0);
  fest::cli::word_option(app, "--placement", o.optimal_placement, {{"optimal", true}, {"vertex", false}},
                         "optimal (quadric minimiser) or vertex (half-edge collapse)")
      ->default_str("optimal");
  using fest::decimate::Weighting;
  fest::cli::word_option(app, "--weighting", o.weighting,
                         {{"sqrt-area", Weighting::sqrt_area}, {"area", Weighting::area}, {"uniform", Weighting::uniform}},
                         "Plane weights of the quadrics: sqrt-area (default), area (GH97), uniform")
      ->default_str("sqrt-area");
  app.add_flag("--drop-nonmanifold", o.drop_nonmanifold, "Drop faces the reader could not attach instead of refusing");
  app.add_flag("--ascii", o.ascii, "ASCII PLY/STL output");
  app.add_option("--report", o.report, "Write counts, time, Hausdorff and RMS error (input vs output) as JSON");
  app.add_option("--samples", o.samples, "Extra area-weighted samples of the error measurement")->default_val(100000)->check(fest::cli::range(0, 100000000));
  fest::cli::add_threads(app, o.threads);
  fest::cli::add_progress(app, o.progress);
  app.footer("Exit status: 0 success, 2 usage error, 3 bad input, 4 I/O error. See decimate(1).");
  return fest::cli::run(app, argc, argv, [&] {
    ::omerr().disable();
    o.quiet = common.quiet;
    return fest::decimate_tool::run(o);
  });
}

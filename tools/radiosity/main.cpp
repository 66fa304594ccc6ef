// radiosity: progressive-refinement radiosity with over-relaxation, hemicube and ray-cast
// form factors, adaptive elements; lit meshes per object (docs/radiosity.md).
// Flags only: the subcommands live in fest_radiosity_app (commands.hpp).

#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

using fest::radiosity::Engine;
const std::vector<std::pair<std::string, Engine>> kEngines{
    {"hemicube", Engine::hemicube}, {"hybrid", Engine::hybrid}, {"raycast", Engine::raycast}, {"analytic", Engine::analytic}};

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::radiosity_tool;
  CLI::App app{"Diffuse global illumination by progressive refinement radiosity; writes the scene back as\n"
               "meshes with per-vertex radiosity and display colours, one object per input object",
               "radiosity"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.fallthrough();  // -q / -v after the subcommand too

  SolveArgs s;
  CameraArgs cam;
  CLI::App* sv = app.add_subcommand("solve", "Light a scene (JSON) and write the lit PLY");
  sv->add_option("scene", s.scene, "Scene JSON (- or nothing: standard input)");
  sv->add_option("-o,--output", s.output, "Lit PLY (- : standard output)");
  fest::cli::enum_words(
      sv->add_option("--ff", s.ff, "Form factors: hybrid (default: hemicube visibility, exact values), hemicube, raycast or analytic"),
      kEngines);
  sv->add_option("--hemicube-res", s.hemicube_res, "Hemicube top face resolution H (even)")->check(fest::cli::range(2, 8192));
  sv->add_option("--samples", s.samples, "Points per shooter for the ray engines")->check(fest::cli::range(1, 4096));
  fest::cli::enum_words<fest::radiosity::Solver>(sv->add_option("--solver", s.solver, "orpr, pr, sor or overshoot"),
                                                 {{"orpr", fest::radiosity::Solver::orpr},
                                                  {"pr", fest::radiosity::Solver::pr},
                                                  {"sor", fest::radiosity::Solver::sor},
                                                  {"overshoot", fest::radiosity::Solver::overshoot}});
  sv->add_option("--omega", s.omega, "Over-relaxation factor (orpr 1.0, sor 1.5)")->check(fest::cli::range(0.0, 2.0));
  sv->add_option("--tol", s.tol, "Stop when the unshot energy is this fraction of the emitted")
      ->check(fest::cli::range(1e-12, 1.0));
  sv->add_option("--max-shots", s.max_shots, "Shots per level (default 10 x patches)")->check(fest::cli::range(1L, 1000000000L));
  sv->add_option("--levels", s.levels, "Adaptive subdivision rounds")->check(fest::cli::range(0, 8));
  sv->add_option("--grad", s.grad, "Split elements whose luminance step exceeds this fraction of B_max")
      ->check(fest::cli::range(0.0, 1.0));
  sv->add_option("--min-element", s.min_element, "Do not split elements this small (scene units)")
      ->check(fest::cli::non_negative);
  sv->add_option("--patch-size", s.patch_size, "Longest patch edge (default: scene diagonal / 12)")
      ->check(fest::cli::positive);
  sv->add_option("--element-size", s.element_size, "Longest element edge (default: patch size / 4)")
      ->check(fest::cli::positive);
  sv->add_flag("--no-mesh", s.no_mesh, "Every face is one patch and one element");
  sv->add_option("--crease", s.crease, "Vertices are shared across faces within this angle (degrees)")
      ->check(fest::cli::range(0.0, 180.0));
  fest::cli::enum_words<bool>(sv->add_option("--emission", s.emission_is_radiance, "Scene emission is radiance (x pi) or exitance"),
                              {{"radiance", true}, {"exitance", false}});
  sv->add_option("--exposure", s.exposure, "Display colour scale k on L = B/pi (default: 1/99th percentile)")
      ->check(fest::cli::positive);
  sv->add_option("--split-objects", s.split_objects, "Also write one PLY per object into this folder");
  sv->add_option("--log", s.log, "Per-shot CSV: shot, patch, object, unshot_fraction, omega, seconds, level");
  sv->add_option("--report", s.report, "JSON report: shots, time split, radiosity range, energy");
  sv->add_option("--view", s.view, "Render the lit scene to this PNG");
  sv->add_option("--view-width", cam.width, "Width (and height) of the --view picture")->check(fest::cli::range(8, 8192));
  sv->add_option("--eye", cam.eye, "Camera position x,y,z (default: in front of the scene's box)")
      ->delimiter(',')->expected(3);
  sv->add_option("--target", cam.target, "Point looked at x,y,z")->delimiter(',')->expected(3);
  sv->add_option("--up", cam.up, "Up direction x,y,z")->delimiter(',')->expected(3);
  sv->add_option("--fov", cam.fov, "Vertical field of view, degrees")->check(fest::cli::range(1.0, 170.0));
  sv->add_flag("--direct", s.direct, "Also solve (I - rho F) B = E densely and report the largest difference");
  sv->add_flag("--strict", s.strict, "Exit 1 when --max-shots stops the solve before --tol");
  fest::cli::add_threads(*sv, s.threads);
  fest::cli::add_progress(*sv, s.progress);

  CornellArgs c;
  CLI::App* cb = app.add_subcommand("cornell", "Write the built-in Cornell box scene (JSON)");
  cb->add_flag("--no-blocks", c.no_blocks, "Empty box without the two blocks");
  cb->add_option("-o,--output", c.output, "Scene JSON (- : standard output)");

  FormFactorArgs f;
  CLI::App* fc = app.add_subcommand("formfactor", "Print F_AB and F_BA of two polygons (one-face meshes)");
  fc->add_option("a", f.a, "Polygon A (mesh file with one face)")->required();
  fc->add_option("b", f.b, "Polygon B")->required();
  fest::cli::enum_words(fc->add_option("--ff", f.ff, "analytic, hemicube or raycast (hybrid = analytic without occluders)"),
                        kEngines);
  fc->add_option("--hemicube-res", f.hemicube_res, "Hemicube resolution")->check(fest::cli::range(2, 8192));
  fc->add_option("--samples", f.samples, "Points on B for raycast")->check(fest::cli::range(1, 4096));
  fc->add_option("--cells", f.cells, "A (and for the hemicube B) cut into cells x cells")->check(fest::cli::range(1, 256));
  fest::cli::add_threads(*fc, f.threads);

  RenderArgs r;
  CLI::App* rd = app.add_subcommand("render", "Render a lit mesh's vertex colours to PNG (Gouraud)");
  rd->add_option("input", r.input, "Lit PLY (- or nothing: standard input)");
  rd->add_option("-o,--output", r.output, "PNG (- : standard output)");
  rd->add_option("--width", r.camera.width, "Picture width")->check(fest::cli::range(8, 8192));
  rd->add_option("--height", r.camera.height, "Picture height (default: the width)")->check(fest::cli::range(8, 8192));
  rd->add_option("--eye", r.camera.eye, "Camera position x,y,z")->delimiter(',')->expected(3);
  rd->add_option("--target", r.camera.target, "Point looked at x,y,z")->delimiter(',')->expected(3);
  rd->add_option("--up", r.camera.up, "Up direction x,y,z")->delimiter(',')->expected(3);
  rd->add_option("--fov", r.camera.fov, "Vertical field of view, degrees")->check(fest::cli::range(1.0, 170.0));
  fest::cli::add_threads(*rd, r.threads);

  app.footer("Exit status: 0 success, 1 no convergence with --strict or a numerical failure, 2 usage error,\n"
             "3 bad scene, 4 I/O error. See radiosity(1).");
  return fest::cli::run(app, argc, argv, [&] {
    s.quiet = common.quiet;
    if (sv->parsed()) return run_solve(s, cam);
    if (cb->parsed()) return run_cornell(c);
    if (fc->parsed()) return run_formfactor(f);
    return run_render(r);
  });
}

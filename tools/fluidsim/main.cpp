// fluidsim: stable fluids with the chapter's 8-way parallel projection and frame
// interpolation (docs/fluidsim.md). Flags -> typed options; the subcommands live in
// cmd_<sub>.cpp.

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::fluidsim_tool;
using fest::fluidsim::PoissonSolver;
using fest::usage_error;

PoissonSolver poisson_solver(const std::string& name) {
  if (name == "fdm") return PoissonSolver::fdm;
  if (name == "fft") return PoissonSolver::fft;
  if (name == "mg") return PoissonSolver::mg;
  if (name == "gs") return PoissonSolver::gs;
  if (name == "jacobi") return PoissonSolver::jacobi;
  if (name == "pcg") throw usage_error("--poisson pcg is unsupported in this build (use fdm, fft, mg, gs or jacobi)");
  throw usage_error("--poisson must be fdm, fft, mg, gs or jacobi, not \"{}\"", name);
}

// run's frames: the stream on standard output, else --to or the pattern's extension.
FrameFormat frame_format(const std::string& to, const std::string& output) {
  if (output == "-" || output.empty()) {
    if (!to.empty() && to != "nrrd") throw usage_error("standard output carries the NRRD frame stream only");
    return FrameFormat::stream;
  }
  // ".vti": the pattern's extension, or --to with a dot.
  const std::string f = to.empty() ? std::filesystem::path(output).extension().string() : "." + to;
  if (f == ".vti") return FrameFormat::vti;
  if (f == ".nrrd") return FrameFormat::nrrd;
  if (f == ".pfm") return FrameFormat::pfm;
  if (f == ".exr") return FrameFormat::exr;
  if (f == ".png") return FrameFormat::png;
  throw usage_error("output format must be vti, nrrd, pfm, exr or png (from --to or the extension of \"{}\")", output);
}

// --fields a,b: names, none empty ("" : the default set).
std::vector<std::string> field_names(const std::string& text) {
  std::vector<std::string> names;
  if (text.empty()) return names;
  std::string item;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == ',') {
      if (item.empty()) throw usage_error("--fields has an empty name");
      names.push_back(item);
      item.clear();
    } else {
      item += text[i];
    }
  }
  return names;
}

// run's word flags, in the order the command used to check them.
void resolve_run_words(RunOptions& run, const std::string& order, const std::string& grid,
                       const std::string& precision, const std::string& to, const std::string& poisson,
                       const std::string& pipeline, const std::string& fields) {
  if (order != "paper" && order != "stam03") throw usage_error("--order must be paper or stam03");
  run.order = order == "stam03" ? StepOrder::stam03 : StepOrder::paper;
  if (grid == "mac") throw usage_error("--grid mac is unsupported in this build (use collocated)");
  if (grid != "collocated") throw usage_error("--grid must be collocated");
  if (precision != "float" && precision != "double") throw usage_error("--precision must be float or double");
  run.float64 = precision == "double";
  run.format = frame_format(to, run.output);
  if (!poisson.empty()) run.poisson = poisson_solver(poisson);
  run.pipeline = pipeline == "on";
  run.fields = field_names(fields);
}

void resolve_render_words(RenderOptions& ren, const std::string& mode, const std::string& axis,
                          const std::string& to, const std::string& colormap) {
  using fest::fluidsim::Colormap;
  using fest::fluidsim::RenderMode;
  if (mode == "slice") ren.mode = RenderMode::slice;
  else if (mode == "mip") ren.mode = RenderMode::mip;
  else if (mode == "absorb") ren.mode = RenderMode::absorb;
  else throw usage_error("--mode must be slice, mip or absorb");
  if (axis == "x") ren.axis = 0;
  else if (axis == "y") ren.axis = 1;
  else if (axis == "z") ren.axis = 2;
  else throw usage_error("--axis must be x, y or z");
  if (to == "png") ren.to = ImageFormat::png;
  else if (to == "pfm") ren.to = ImageFormat::pfm;
  else throw usage_error("--to must be png or pfm");
  if (colormap == "gray") ren.colormap = Colormap::gray;
  else if (colormap == "inferno") ren.colormap = Colormap::inferno;
  else if (colormap == "velocity") ren.colormap = Colormap::velocity;
  else throw usage_error("--colormap must be gray, inferno or velocity, not \"{}\"", colormap);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Stable fluids on 2-D/3-D grids with an exact, 8-way parallel projection", "fluidsim"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  RunOptions run;
  std::string run_to, run_fields, run_poisson, run_order = "paper", run_grid = "collocated", run_precision = "float",
                                               run_pipeline = "on";
  CLI::App* r = app.add_subcommand("run", "Simulate a scene; frames to files or a frame stream on standard output");
  r->add_option("scene", run.scene, "Scene JSON (- or nothing: standard input)");
  r->add_option("-o,--output", run.output,
                "Frame pattern with %d (f%05d.vti, .nrrd, 2-D: .pfm .exr .png), or - for the frame stream");
  r->add_option("--to", run_to, "Format when the pattern has no extension: nrrd, vti, pfm, exr, png");
  r->add_option("--fields", run_fields, "Fields to write, comma-separated (default: velocity and every scalar)");
  r->add_option("--frames", run.frames, "Number of output frames (overrides the scene)")->check(fest::cli::range(1, 10000000));
  r->add_option("--interp", run.interp, "Simulation step = K frame intervals; frames between are interpolated")
      ->check(fest::cli::range(1, 1000));
  r->add_option("--poisson", run_poisson, "Pressure solver: fdm, fft, mg, gs, jacobi (default fdm up to 64, else fft)");
  r->add_option("--iters", run.iters, "Sweeps of gs/jacobi")->check(fest::cli::range(1, 100000));
  r->add_option("--tol", run.tol, "Relative residual of mg")->check(fest::cli::range(1e-15, 1.0));
  r->add_option("--order", run_order, "Step order: paper or stam03");
  r->add_option("--grid", run_grid, "Grid: collocated (the paper's)");
  r->add_option("--precision", run_precision, "Output values: float or double");
  r->add_flag("--mass-correct", run.mass_correct, "Rescale each scalar after advection to keep its weighted sum");
  r->add_option("--pipeline", run_pipeline, "on: the solver thread runs ahead of the frame writer (3-slot ring); off: one thread")
      ->check(CLI::IsMember({"on", "off"}));
  r->add_option("--report", run.report, "Write totals and figures as JSON");
  r->add_option("--stats", run.stats, "Write one JSON line of figures per frame");
  fest::cli::add_progress(*r, run.progress);
  fest::cli::add_threads(*r, run.threads);

  RenderOptions ren;
  std::string ren_to = "png", ren_mode = "absorb", ren_axis = "z", ren_colormap = "inferno";
  CLI::App* d = app.add_subcommand("render", "Turn a field file or a frame stream into PNG (or PFM) images");
  d->add_option("input", ren.input, "Frame stream or frame file (- or nothing: standard input)");
  d->add_option("-o,--output", ren.output, "Image, a pattern with %d for a stream, or - (concatenated images)");
  d->add_option("--to", ren_to, "png or pfm");
  d->add_option("--mode", ren_mode, "slice, mip or absorb");
  d->add_option("--axis", ren_axis, "Viewing axis: x, y or z");
  d->add_option("--index", ren.index, "Slice index (default: the middle)")->check(fest::cli::range(0, 2147483647));
  d->add_option("--field", ren.field, "Field to show (velocity: its magnitude)");
  d->add_option("--range", ren.range, "lo,hi mapped to the colour map ends")->delimiter(',')->expected(2)->allow_extra_args(false);
  d->add_option("--colormap", ren_colormap, "gray, inferno or velocity");
  d->add_option("--sigma", ren.sigma, "Absorb: extinction per unit field per unit length")->check(fest::cli::range(0.0, 1e9));
  d->add_option("--depth", ren.depth, "PNG bits per channel: 8 or 16")->check(CLI::IsMember({8, 16}));
  fest::cli::add_progress(*d, ren.progress);

  InterpOptions ip;
  CLI::App* i = app.add_subcommand("interp", "Linear blend (1-a) A + a B of two frames of identical shape");
  i->add_option("a", ip.a, "First frame (NRRD frame file)")->required();
  i->add_option("b", ip.b, "Second frame")->required();
  i->add_option("--alpha", ip.alpha, "Blend weight a of B")->required()->check(fest::cli::range(0.0, 1.0));
  i->add_option("-o,--output", ip.output, "Output frame (- : standard output)");

  CheckOptions ck;
  CLI::App* c = app.add_subcommand("check", "Run an analytic case and print its JSON report; exit 1 when it fails");
  fest::cli::enum_words<CheckCase>(c->add_option("case", ck.which, "taylor-green, abc, projection, interp, mass, stability or all"),
                                   {{"taylor-green", CheckCase::taylor_green},
                                    {"abc", CheckCase::abc},
                                    {"projection", CheckCase::projection},
                                    {"interp", CheckCase::interp},
                                    {"mass", CheckCase::mass},
                                    {"stability", CheckCase::stability},
                                    {"all", CheckCase::all}});
  c->add_option("--n", ck.n, "Resolution of the large-step run (taylor-green, abc) or the grid (stability)")
      ->check(fest::cli::range(8, 512));
  c->add_option("--dt", ck.dt, "Step of the large-step run")->check(fest::cli::range(1e-6, 10.0));
  c->add_option("--nu", ck.nu, "Viscosity of the decay cases")->check(fest::cli::range(0.0, 10.0));
  c->add_option("--report", ck.report, "Also write the report to this file");
  fest::cli::add_threads(*c, ck.threads);
  fest::cli::add_progress(*c, ck.progress);

  BenchOptions bo;
  std::vector<std::string> bench_poisson;
  CLI::App* b = app.add_subcommand("bench", "Time the stages per (size, threads, solver); one JSON line each");
  b->add_option("--sizes", bo.sizes, "Cubic grid sizes")->delimiter(',')->allow_extra_args(false)->check(fest::cli::range(3, 1024));
  b->add_option("--threads", bo.threads, "Thread counts")->delimiter(',')->allow_extra_args(false)->check(fest::cli::range(1, 1024));
  b->add_option("--steps", bo.steps, "Steps per measurement")->check(fest::cli::range(1, 100000));
  b->add_option("--nu", bo.nu, "Viscosity of the bench scene (0: no diffusion stage)")->check(fest::cli::range(0.0, 1.0));
  b->add_option("--poisson", bench_poisson, "Solvers to compare")->delimiter(',')->allow_extra_args(false);

  return fest::cli::run(app, argc, argv, [&] {
    if (*r) {
      run.quiet = common.quiet;
      resolve_run_words(run, run_order, run_grid, run_precision, run_to, run_poisson, run_pipeline, run_fields);
      return run_command(run);
    }
    if (*d) {
      resolve_render_words(ren, ren_mode, ren_axis, ren_to, ren_colormap);
      return render_command(ren);
    }
    if (*i) return interp_command(ip);
    if (*c) return check_command(ck);
    if (!bench_poisson.empty()) {
      bo.poisson.clear();
      for (const std::string& name : bench_poisson) bo.poisson.push_back(poisson_solver(name));
    }
    return bench_command(bo);
  });
}

// fluidsim: stable fluids with the chapter's 8-way parallel projection and frame
// interpolation (docs/fluidsim.md). Flags only; the subcommands live in *_command.cpp.

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::fluidsim_tool;
  CLI::App app{"Stable fluids on 2-D/3-D grids with an exact, 8-way parallel projection", "fluidsim"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  RunOptions run;
  CLI::App* r = app.add_subcommand("run", "Simulate a scene; frames to files or a frame stream on standard output");
  r->add_option("scene", run.scene, "Scene JSON (- or nothing: standard input)");
  r->add_option("-o,--output", run.output,
                "Frame pattern with %d (f%05d.vti, .nrrd, 2-D: .pfm .exr .png), or - for the frame stream");
  r->add_option("--to", run.to, "Format when the pattern has no extension: nrrd, vti, pfm, exr, png");
  r->add_option("--fields", run.fields, "Fields to write, comma-separated (default: velocity and every scalar)");
  r->add_option("--frames", run.frames, "Number of output frames (overrides the scene)")->check(CLI::Range(1, 10000000));
  r->add_option("--interp", run.interp, "Simulation step = K frame intervals; frames between are interpolated")
      ->check(CLI::Range(1, 1000));
  r->add_option("--poisson", run.poisson, "Pressure solver: fdm, fft, mg, gs, jacobi (default fdm up to 64, else fft)");
  r->add_option("--iters", run.iters, "Sweeps of gs/jacobi")->check(CLI::Range(1, 100000));
  r->add_option("--tol", run.tol, "Relative residual of mg")->check(CLI::Range(1e-15, 1.0));
  r->add_option("--order", run.order, "Step order: paper or stam03");
  r->add_option("--grid", run.grid, "Grid: collocated (the paper's)");
  r->add_option("--precision", run.precision, "Output values: float or double");
  r->add_flag("--mass-correct", run.mass_correct, "Rescale each scalar after advection to keep its weighted sum");
  r->add_option("--pipeline", run.pipeline, "on: the solver thread runs ahead of the frame writer (3-slot ring); off: one thread")
      ->check(CLI::IsMember({"on", "off"}));
  r->add_option("--report", run.report, "Write totals and figures as JSON");
  r->add_option("--stats", run.stats, "Write one JSON line of figures per frame");
  r->add_flag("--progress", run.progress, "Show a progress bar");
  fest::cli::add_threads(*r, run.threads);

  RenderOptions ren;
  CLI::App* d = app.add_subcommand("render", "Turn a field file or a frame stream into PNG (or PFM) images");
  d->add_option("input", ren.input, "Frame stream or frame file (- or nothing: standard input)");
  d->add_option("-o,--output", ren.output, "Image, a pattern with %d for a stream, or - (concatenated images)");
  d->add_option("--to", ren.to, "png or pfm");
  d->add_option("--mode", ren.mode, "slice, mip or absorb");
  d->add_option("--axis", ren.axis, "Viewing axis: x, y or z");
  d->add_option("--index", ren.index, "Slice index (default: the middle)");
  d->add_option("--field", ren.field, "Field to show (velocity: its magnitude)");
  d->add_option("--range", ren.range, "lo,hi mapped to the colour map ends")->delimiter(',')->expected(2)->allow_extra_args(false);
  d->add_option("--colormap", ren.colormap, "gray, inferno or velocity");
  d->add_option("--sigma", ren.sigma, "Absorb: extinction per unit field per unit length")->check(CLI::Range(0.0, 1e9));
  d->add_option("--depth", ren.depth, "PNG bits per channel: 8 or 16")->check(CLI::IsMember({8, 16}));

  InterpOptions ip;
  CLI::App* i = app.add_subcommand("interp", "Linear blend (1-a) A + a B of two frames of identical shape");
  i->add_option("a", ip.a, "First frame (NRRD frame file)")->required();
  i->add_option("b", ip.b, "Second frame")->required();
  i->add_option("--alpha", ip.alpha, "Blend weight a of B")->required()->check(CLI::Range(0.0, 1.0));
  i->add_option("-o,--output", ip.output, "Output frame (- : standard output)");

  CheckOptions ck;
  CLI::App* c = app.add_subcommand("check", "Run an analytic case and print its JSON report; exit 1 when it fails");
  c->add_option("case", ck.which, "taylor-green, abc, projection, interp, mass, stability or all")
      ->check(CLI::IsMember({"taylor-green", "abc", "projection", "interp", "mass", "stability", "all"}));
  c->add_option("--n", ck.n, "Resolution of the large-step run (taylor-green, abc) or the grid (stability)")
      ->check(CLI::Range(8, 512));
  c->add_option("--dt", ck.dt, "Step of the large-step run")->check(CLI::Range(1e-6, 10.0));
  c->add_option("--nu", ck.nu, "Viscosity of the decay cases")->check(CLI::Range(0.0, 10.0));
  c->add_option("--report", ck.report, "Also write the report to this file");
  fest::cli::add_threads(*c, ck.threads);

  BenchOptions bo;
  CLI::App* b = app.add_subcommand("bench", "Time the stages per (size, threads, solver); one JSON line each");
  b->add_option("--sizes", bo.sizes, "Cubic grid sizes")->delimiter(',')->allow_extra_args(false)->check(CLI::Range(3, 1024));
  b->add_option("--threads", bo.threads, "Thread counts")->delimiter(',')->allow_extra_args(false)->check(CLI::Range(1, 1024));
  b->add_option("--steps", bo.steps, "Steps per measurement")->check(CLI::Range(1, 100000));
  b->add_option("--nu", bo.nu, "Viscosity of the bench scene (0: no diffusion stage)")->check(CLI::Range(0.0, 1.0));
  b->add_option("--poisson", bo.poisson, "Solvers to compare")->delimiter(',')->allow_extra_args(false);

  return fest::cli::run(app, argc, argv, [&] {
    if (*r) {
      run.quiet = common.quiet;
      return run_command(run);
    }
    if (*d) return render_command(ren);
    if (*i) return interp_command(ip);
    if (*c) return check_command(ck);
    return bench_command(bo);
  });
}

// lbmsim: lattice-Boltzmann flow solver (D2Q9/D3Q19, BGK/TRT). Flags only; the
// subcommands live in the fest_lbmsim_app library (cmd_*.cpp).

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::lbmsim;
  CLI::App app{"Lattice-Boltzmann flow solver (D2Q9/D3Q19, BGK/TRT) writing VTK/NRRD grids", "lbmsim"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.set_version_flag("--version", "lbmsim (fest) " FEST_VERSION ", " + build_features());
  app.require_subcommand(1);
  int threads = 0;

  RunOptions run;
  CLI::App* r = app.add_subcommand("run", "Simulate a case; fields to VTI/NRRD files or a frame stream on standard output");
  r->add_option("case", run.case_file, "Case JSON (- or nothing: standard input)");
  r->add_option("-o,--output", run.output, "Pattern with %d (out/f%05d.vti, .nrrd), or - for the frame stream");
  r->add_option("--to", run.to, "vti, nrrd or stream (default: from the extension)");
  r->add_option("--fields", run.fields, "Fields, comma-separated: density,velocity,pressure,speed,vorticity,vorticity_mag,qcriterion,flags");
  r->add_option("--every", run.every, "Write every K steps (0: last step only)")->check(CLI::Range(0L, 2000000000L));
  r->add_option("--steps", run.steps, "Number of steps (overrides the case)")->check(CLI::Range(0L, 2000000000L));
  r->add_option("--precision", run.precision, "Arithmetic: double or float")->check(CLI::IsMember({"double", "float"}));
  r->add_option("--forces", run.forces, "CSV of forces on the case's monitored flags per step (- : standard output)");
  r->add_option("--probes", run.probes, "CSV of the probes per step");
  r->add_option("--report", run.report, "Write units, timings, MLUPS, mass drift and forces as JSON");
  r->add_option("--set", run.set, "Override a case key: key.sub=value (repeatable)");
  r->add_option("--compress", run.compress, "zlib in .vti: on or off")->check(CLI::IsMember({"on", "off"}));
  fest::cli::add_threads(*r, threads);

  CheckOptions ck;
  CLI::App* c = app.add_subcommand("check", "Run a validation case; print its JSON report; exit 1 when it fails");
  c->add_option("case", ck.which,
                "poiseuille, taylor-green, cavity, cavity400, cavity1000, cylinder20, mass, symmetry, determinism, "
                "all-fast or all")
      ->check(CLI::IsMember({"poiseuille", "taylor-green", "cavity", "cavity400", "cavity1000", "cylinder20", "mass",
                             "symmetry", "determinism", "all-fast", "all"}));
  c->add_option("--n", ck.n, "Resolution (cavity N, cylinder D in cells)")->check(CLI::Range(8, 1024));
  c->add_option("--report", ck.report, "Also write the report to this file");
  fest::cli::add_threads(*c, threads);

  BenchOptions bo;
  CLI::App* b = app.add_subcommand("bench", "Measure MLUPS of a periodic box next to the copy bandwidth; JSON lines");
  b->add_option("--lattice", bo.lattice, "d2q9 or d3q19")->check(CLI::IsMember({"d2q9", "d3q19"}));
  b->add_option("--size", bo.size, "Cells per axis (default 128 for d3q19, 1024 for d2q9)")->check(CLI::Range(8, 4096));
  b->add_option("--steps", bo.steps, "Timed steps (after 10 warm-up steps)")->check(CLI::Range(1, 1000000));
  b->add_option("--precision", bo.precision, "double,float")->delimiter(',')->check(CLI::IsMember({"double", "float"}));
  b->add_option("--threads", bo.threads, "Thread counts, e.g. 1,2")->delimiter(',')->check(CLI::Range(1, 1024));
  b->add_option("--collision", bo.collision, "bgk or trt")->check(CLI::IsMember({"bgk", "trt"}));

  VoxelizeOptions vo;
  CLI::App* v = app.add_subcommand("voxelize", "Voxelize a closed triangle mesh into a uint8 flag volume (NRRD)");
  v->add_option("mesh", vo.mesh, "Mesh (PLY, OBJ, OFF, STL, DRC; - : standard input)")->required();
  v->add_option("--size", vo.size, "nx,ny,nz")->delimiter(',')->expected(3)->check(CLI::Range(1, 4096));
  v->add_option("--fit", vo.fit, "box (scale into the lattice) or none (mesh coordinates are cells)")
      ->check(CLI::IsMember({"box", "none"}));
  v->add_option("--margin", vo.margin, "Free cells around the fitted mesh")->check(CLI::Range(0.0, 1e6));
  v->add_option("-o,--output", vo.output, "Flag volume (.nrrd, .mha, .nii; - : NRRD on standard output)");

  InfoOptions io;
  CLI::App* i = app.add_subcommand("info", "Print the unit table of a case: Re, Ma, tau, memory, a speed estimate");
  i->add_option("case", io.case_file, "Case JSON (- or nothing: standard input)");
  i->add_option("--set", io.set, "Override a case key: key.sub=value (repeatable)");
  i->add_option("--precision", io.precision, "double or float")->check(CLI::IsMember({"double", "float"}));
  i->add_flag("--json", io.json, "Print the table as JSON");

  return fest::cli::run(app, argc, argv, [&] {
    if (*r) {
      set_threads(threads);
      run.quiet = common.quiet;
      return run_command(run);
    }
    if (*c) {
      set_threads(threads);
      return check_command(ck);
    }
    if (*b) return bench_command(bo);
    if (*v) return voxelize_command(vo);
    return info_command(io);
  });
}

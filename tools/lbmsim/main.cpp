// lbmsim: lattice-Boltzmann flow solver (D2Q9/D3Q19, BGK/TRT). Flags -> typed options;
// the subcommands live in the fest_lbmsim_app library (cmd_<sub>.cpp).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::lbmsim_tool;
using fest::usage_error;
namespace lbm = fest::lbm;

const std::vector<std::pair<std::string, lbm::Precision>> kPrecisions{{"double", lbm::Precision::f64},
                                                                      {"float", lbm::Precision::f32}};

// run's fields: the stream on standard output, else --to or the pattern's extension.
FieldFormat field_format(const std::string& to, const std::string& output) {
  if (output.empty() || output == "-") {
    if (!to.empty() && to != "stream" && to != "nrrd")
      throw usage_error("standard output carries the frame stream only (--to stream)");
    return FieldFormat::stream;
  }
  // ".vti": the pattern's extension, or --to with a dot.
  const std::string f = to.empty() ? std::filesystem::path(output).extension().string() : "." + to;
  if (f == ".vti") return FieldFormat::vti;
  if (f == ".nrrd") return FieldFormat::nrrd;
  throw usage_error("output format must be vti or nrrd (from --to or the extension of \"{}\"), or - for the stream",
                    output);
}

// --fields a,b: the names (empty items skipped).
std::vector<std::string> field_names(const std::string& text) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    if (end > begin) out.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return out;
}

// --set a.b=value -> the key path and the value's text; lib's message after the flag.
std::vector<lbm::CaseOverride> case_overrides(const std::vector<std::string>& assignments) {
  std::vector<lbm::CaseOverride> out;
  for (const std::string& a : assignments) {
    try {
      out.push_back(lbm::parse_override(a));
    } catch (const fest::Error& e) {
      throw usage_error("--set {}", e.what());
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lattice-Boltzmann flow solver (D2Q9/D3Q19, BGK/TRT) writing VTK/NRRD grids", "lbmsim"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.set_version_flag("--version", "lbmsim (fest) " FEST_VERSION ", " + build_features());
  app.require_subcommand(1);
  int threads = 0;

  RunOptions run;
  std::string run_to, run_fields, run_compress;
  std::vector<std::string> run_set, info_set;
  CLI::App* r = app.add_subcommand("run", "Simulate a case; fields to VTI/NRRD files or a frame stream on standard output");
  r->add_option("case", run.case_file, "Case JSON (- or nothing: standard input)");
  r->add_option("-o,--output", run.output, "Pattern with %d (out/f%05d.vti, .nrrd), or - for the frame stream");
  r->add_option("--to", run_to, "vti, nrrd or stream (default: from the extension)");
  r->add_option("--fields", run_fields, "Fields, comma-separated: density,velocity,pressure,speed,vorticity,vorticity_mag,qcriterion,flags");
  r->add_option("--every", run.every, "Write every K steps (0: last step only)")->check(fest::cli::range(0L, 2000000000L));
  r->add_option("--steps", run.steps, "Number of steps (overrides the case)")->check(fest::cli::range(0L, 2000000000L));
  fest::cli::enum_words(r->add_option("--precision", run.precision, "Arithmetic: double or float"), kPrecisions);
  r->add_option("--forces", run.forces, "CSV of forces on the case's monitored flags per step (- : standard output)");
  r->add_option("--probes", run.probes, "CSV of the probes per step");
  fest::cli::add_progress(*r, run.progress);
  r->add_option("--report", run.report, "Write units, timings, MLUPS, mass drift and forces as JSON");
  r->add_option("--set", run_set, "Override a case key: key.sub=value (repeatable)");
  r->add_option("--compress", run_compress, "zlib in .vti: on or off")->check(CLI::IsMember({"on", "off"}));
  fest::cli::add_threads(*r, threads);

  CheckOptions ck;
  CLI::App* c = app.add_subcommand("check", "Run a validation case; print its JSON report; exit 1 when it fails");
  c->add_option("case", ck.which,
                "poiseuille, taylor-green, cavity, cavity400, cavity1000, cylinder20, mass, symmetry, determinism, "
                "all-fast or all")
      ->check(CLI::IsMember({"poiseuille", "taylor-green", "cavity", "cavity400", "cavity1000", "cylinder20", "mass",
                             "symmetry", "determinism", "all-fast", "all"}));
  c->add_option("--n", ck.n, "Resolution (cavity N, cylinder D in cells)")->check(fest::cli::range(8, 1024));
  c->add_option("--report", ck.report, "Also write the report to this file");
  fest::cli::add_threads(*c, threads);
  fest::cli::add_progress(*c, ck.progress);

  BenchOptions bo;
  CLI::App* b = app.add_subcommand("bench", "Measure MLUPS of a periodic box next to the copy bandwidth; JSON lines");
  fest::cli::enum_words<lbm::LatticeKind>(b->add_option("--lattice", bo.lattice, "d2q9 or d3q19"),
                                          {{"d2q9", lbm::LatticeKind::d2q9}, {"d3q19", lbm::LatticeKind::d3q19}});
  b->add_option("--size", bo.size, "Cells per axis (default 128 for d3q19, 1024 for d2q9)")->check(fest::cli::range(8, 4096));
  b->add_option("--steps", bo.steps, "Timed steps (after 10 warm-up steps)")->check(fest::cli::range(1, 1000000));
  fest::cli::enum_words(b->add_option("--precision", bo.precision, "double,float")->delimiter(','), kPrecisions);
  b->add_option("--threads", bo.threads, "Thread counts, e.g. 1,2")->delimiter(',')->check(fest::cli::range(1, 1024));
  fest::cli::enum_words<lbm::CollisionModel>(b->add_option("--collision", bo.collision, "bgk or trt"),
                                             {{"bgk", lbm::CollisionModel::bgk}, {"trt", lbm::CollisionModel::trt}});

  VoxelizeOptions vo;
  CLI::App* v = app.add_subcommand("voxelize", "Voxelize a closed triangle mesh into a uint8 flag volume (NRRD)");
  v->add_option("mesh", vo.mesh, "Mesh (PLY, OBJ, OFF, STL, DRC; - : standard input)")->required();
  v->add_option("--size", vo.size, "nx,ny,nz")->delimiter(',')->expected(3)->check(fest::cli::range(1, 4096));
  fest::cli::enum_words<bool>(v->add_option("--fit", vo.fit_box, "box (scale into the lattice) or none (mesh coordinates are cells)"),
                              {{"box", true}, {"none", false}});
  v->add_option("--margin", vo.margin, "Free cells around the fitted mesh")->check(fest::cli::range(0.0, 1e6));
  v->add_option("-o,--output", vo.output, "Flag volume (.nrrd, .mha, .nii; - : NRRD on standard output)");

  InfoOptions io;
  CLI::App* i = app.add_subcommand("info", "Print the unit table of a case: Re, Ma, tau, memory, a speed estimate");
  i->add_option("case", io.case_file, "Case JSON (- or nothing: standard input)");
  i->add_option("--set", info_set, "Override a case key: key.sub=value (repeatable)");
  fest::cli::enum_words(i->add_option("--precision", io.precision, "double or float"), kPrecisions);
  i->add_flag("--json", io.json, "Print the table as JSON");

  return fest::cli::run(app, argc, argv, [&] {
    if (*r) {
      set_threads(threads);
      run.quiet = common.quiet;
      run.format = field_format(run_to, run.output);
      if (!run_fields.empty()) run.fields = field_names(run_fields);
      if (!run_compress.empty()) run.compress = run_compress == "on";
      run.set = case_overrides(run_set);
      return run_command(run);
    }
    if (*c) {
      set_threads(threads);
      return check_command(ck);
    }
    if (*b) return bench_command(bo);
    if (*v) return voxelize_command(vo);
    io.set = case_overrides(info_set);
    return info_command(io);
  });
}

// hdrmerge: camera response recovery (Debevec & Malik 1997) and the merge of an exposure
// series into a radiance image (docs/hdrmerge.md).
//
// Wiring only: flags -> the typed options of commands.hpp, one call per subcommand.

#include <utility>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"
#include "stack_files.hpp"

namespace {

using namespace fest;
using namespace fest::hdrmerge_tool;

const std::vector<std::pair<std::string, Method>> kMethods{{"debevec", Method::debevec}, {"robertson", Method::robertson}};
const std::vector<std::pair<std::string, formats::Format>> kRadianceFormats{{"exr", formats::Format::exr}, {"pfm", formats::Format::pfm}};

// "0.001", "1e-3", "1/1000" -> seconds (a usage error otherwise).
std::vector<double> seconds(const std::vector<std::string>& times) {
  std::vector<double> out;
  for (const std::string& t : times) out.push_back(parse_exposure_time(t));
  return out;
}

void add_series(CLI::App* cmd, SeriesOptions& s, std::vector<std::string>& times) {
  cmd->add_option("images", s.images, "The exposures (8-bit PNG, PPM/PGM, TIFF), one per time")->required();
  cmd->add_option("-t,--times", times, "Exposure times in seconds, in image order, increasing: 1/1000,1/250,...")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_option("--samples", s.samples, "Sample pixels per channel for response recovery")->check(fest::cli::range(1, 100000));
  cmd->add_option("--lambda", s.lambda, "Smoothness weight of the response (as in Debevec-Malik's gsolve)")
      ->check(fest::cli::non_negative);
  fest::cli::enum_words(cmd->add_option("--method", s.method, "Response recovery: debevec (Debevec-Malik) or robertson (Robertson et al.)"), kMethods);
}

}  // namespace

int main(int argc, char** argv) {
  // `hdrmerge IMG...` means `hdrmerge merge IMG...` (merge is the default subcommand).
  std::vector<char*> args(argv, argv + argc);
  static char merge_name[] = "merge";
  static char session_name[] = "session";
  if (argc > 1) {
    const std::string first = argv[1];
    const bool known = first == "merge" || first == "calibrate" || first == "bracket" || first == "session" || first == "sheet" ||
                       first == "--help" || first == "-h" || first == "--version";
    // `hdrmerge --manifest M` means `hdrmerge session --manifest M`.
    bool manifest = false;
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--manifest" || std::string(argv[i]).rfind("--manifest=", 0) == 0) manifest = true;
    if (!known) args.insert(args.begin() + 1, manifest ? session_name : merge_name);
  }
  CLI::App app{"Camera response recovery (Debevec & Malik 1997) and merging of an exposure series into\n"
               "a high-dynamic-range radiance image.",
               "hdrmerge"};
  cli::Common common;
  cli::add_common(app, common);
  app.require_subcommand(1);

  MergeOptions merge;
  std::vector<std::string> merge_times;
  auto* merge_cmd = app.add_subcommand("merge", "Merge one exposure series into a radiance image (the default)");
  add_series(merge_cmd, merge.series, merge_times);
  merge_cmd->add_option("-o,--output", merge.output, "Radiance image (.exr or .pfm), - = standard output (EXR)");
  fest::cli::enum_words(merge_cmd->add_option("--to", merge.to, "Output format: exr or pfm"), kRadianceFormats);
  merge_cmd->add_flag("--float", merge.full_float, "EXR with 32-bit float channels instead of half");
  merge_cmd->add_option("--response", merge.response_in, "Use this response curve (CSV of hdrmerge calibrate)");
  merge_cmd->add_option("--response-out", merge.response_out, "Also write the response curve used (CSV)");
  merge_cmd->add_option("--valid", merge.valid_out, "Also write the validity map (EXR, fraction of full hat weight)");
  cli::add_threads(*merge_cmd, merge.threads);
  cli::add_progress(*merge_cmd, merge.progress);

  CalibrateOptions calibrate;
  std::vector<std::string> calibrate_times;
  auto* calibrate_cmd = app.add_subcommand("calibrate", "Recover the response curve only: CSV z,gR,gG,gB");
  add_series(calibrate_cmd, calibrate.series, calibrate_times);
  calibrate_cmd->add_option("-o,--output", calibrate.output, "Response CSV, - = standard output");
  cli::add_progress(*calibrate_cmd, calibrate.progress);

  BracketOptions bracket;
  std::vector<std::string> bracket_times;
  auto* bracket_cmd = app.add_subcommand("bracket", "Simulated camera: expose a radiance image into 8-bit PNGs DIR/eNN.png");
  bracket_cmd->add_option("radiance", bracket.radiance, "Radiance image (EXR or PFM, grey or RGB)")->required();
  bracket_cmd->add_option("-t,--times", bracket_times, "Exposure times in seconds")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);
  bracket_cmd->add_option("-o,--output", bracket.directory, "Existing folder for e00.png, e01.png, ...")->required();
  bracket_cmd->add_option("--gamma", bracket.camera.gamma, "Response Z = 255 (E t)^(1/gamma)")->check(fest::cli::positive);
  bracket_cmd->add_option("--noise", bracket.camera.noise_dn, "Read noise, standard deviation in DN")
      ->check(fest::cli::non_negative);
  bracket_cmd->add_option("--scale", bracket.scale, "Multiply the radiance first")->check(fest::cli::positive);
  bracket_cmd->add_option("--seed", bracket.seed, "Noise seed (exposure k uses seed + k)");
  bracket_cmd->add_option("--response-out", bracket.response_out, "Also write the true response curve (CSV, g(128) = 0)");
  cli::add_progress(*bracket_cmd, bracket.progress);

  SessionOptions session;
  auto* session_cmd = app.add_subcommand(
      "session", "A capture session: merge every (angle, light) set, mask every silhouette, rig JSON on stdout "
                 "(also: hdrmerge --manifest M)");
  session_cmd->add_option("--manifest", session.manifest, "The session's manifest.json, - = standard input")->required();
  session_cmd->add_option("-o,--output", session.output_dir, "Folder for the EXRs and masks (default SESSION/hdr)");
  session_cmd->add_option("--response", session.response_in, "Use this response curve (CSV) instead of recovering one");
  fest::cli::enum_words(session_cmd->add_option("--method", session.method, "Response recovery: debevec or robertson"), kMethods);
  session_cmd->add_option("--samples", session.samples, "Sample pixels per channel for response recovery")
      ->check(fest::cli::range(1, 100000));
  session_cmd->add_option("--lambda", session.lambda, "Smoothness weight of the response")->check(fest::cli::non_negative);
  session_cmd->add_flag("--float", session.full_float, "EXR with 32-bit float channels instead of half");
  cli::add_threads(*session_cmd, session.threads);
  cli::add_progress(*session_cmd, session.progress);

  SheetOptions sheet;
  auto* sheet_cmd = app.add_subcommand("sheet", "A contact sheet of radiance images: one exposure for all, sRGB, PNG");
  sheet_cmd->add_option("images", sheet.images, "Radiance images (EXR, PFM)")->required();
  sheet_cmd->add_option("-o,--output", sheet.output, "PNG file, - = standard output")->required();
  sheet_cmd->add_option("--columns", sheet.columns, "Tiles per row")->check(fest::cli::range(1, 1000));
  sheet_cmd->add_option("--width", sheet.width, "Tile width in pixels")->check(fest::cli::range(8, 10000));

  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See hdrmerge(1).");
  const int n = static_cast<int>(args.size());
  return cli::run(app, n, args.data(), [&] {
    if (merge_cmd->parsed()) {
      merge.series.times = seconds(merge_times);
      return run_merge(merge);
    }
    if (bracket_cmd->parsed()) {
      bracket.times = seconds(bracket_times);
      return run_bracket(bracket);
    }
    if (session_cmd->parsed()) return run_session(session);
    if (sheet_cmd->parsed()) return run_sheet(sheet);
    calibrate.series.times = seconds(calibrate_times);
    return run_calibrate(calibrate);
  });
}

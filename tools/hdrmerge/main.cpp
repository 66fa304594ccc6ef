// hdrmerge: camera response recovery (Debevec & Malik 1997) and the merge of an exposure
// series into a radiance image (specs/capture.md §2.8).
//
// Wiring only: flags -> stack_files (formats) -> lib/hdr -> formats.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "hdr/bracket.hpp"
#include "hdr/contact_sheet.hpp"
#include "hdr/merge.hpp"
#include "hdr/robertson.hpp"
#include "manifest_mode.hpp"
#include "stack_files.hpp"

namespace {

using namespace fest;
using namespace fest::hdrmerge_tool;

struct SeriesArgs {
  std::vector<std::string> images;
  std::vector<std::string> times;
  int samples = hdr::DebevecOptions{}.samples;
  double lambda = hdr::DebevecOptions{}.lambda;
  std::string method = "debevec";
};

struct MergeArgs {
  SeriesArgs series;
  std::string output = "-";
  std::string to;
  bool full_float = false;
  std::string response_in, response_out, valid_out;
  int threads = 0;
};

void add_series(CLI::App* cmd, SeriesArgs& s) {
  cmd->add_option("images", s.images, "The exposures (8-bit PNG, PPM/PGM, TIFF), one per time")->required();
  cmd->add_option("-t,--times", s.times, "Exposure times in seconds, in image order, increasing: 1/1000,1/250,...")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_option("--samples", s.samples, "Sample pixels per channel for response recovery")->check(CLI::Range(1, 100000));
  cmd->add_option("--lambda", s.lambda, "Smoothness weight of the response (as in Debevec-Malik's gsolve)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--method", s.method, "Response recovery: debevec (Debevec-Malik) or robertson (Robertson et al.)")
      ->check(CLI::IsMember({"debevec", "robertson"}));
}

hdr::DebevecOptions options_of(const SeriesArgs& s) {
  hdr::DebevecOptions o;
  o.samples = s.samples;
  o.lambda = s.lambda;
  return o;
}

hdr::Response recover(const hdr::ExposureStack& stack, const SeriesArgs& s) {
  if (s.method == "robertson") return hdr::recover_response_robertson(stack);
  return hdr::recover_response_debevec(stack, options_of(s));
}

formats::Format radiance_format(const MergeArgs& a) {
  formats::OutputFormat f{formats::Format::exr, false};
  if (!a.to.empty())
    f = formats::output_format_from_name(a.to);
  else if (!is_stdio(a.output))
    f = formats::output_format_from_path(a.output);
  if (f.gzip || (f.format != formats::Format::exr && f.format != formats::Format::pfm))
    throw usage_error("radiance output must be exr or pfm, not {}", formats::format_name(f.format));
  return f.format;
}

int run_merge(const MergeArgs& a) {
  const formats::Format format = radiance_format(a);
  const int threads = resolve_threads(a.threads);
  const hdr::ExposureStack stack = read_stack(a.series.images, a.series.times);
  const hdr::Response response =
      a.response_in.empty()
          ? recover(stack, a.series)
          : response_from_table(formats::parse(formats::load_input(a.response_in), formats::read_table));
  const hdr::MergeResult merged = hdr::merge_debevec(stack, response, threads);
  formats::ImageWriteOptions w;
  w.exr_half = format == formats::Format::exr && !a.full_float;
  // Everything is encoded before anything is written: a failure leaves no file behind.
  const std::string radiance = formats::write_image(Image{merged.radiance, ColorSpace::linear}, format, w);
  std::string valid, curve;
  if (!a.valid_out.empty()) valid = formats::write_image(Image{merged.valid, ColorSpace::linear}, formats::Format::exr, {});
  if (!a.response_out.empty()) curve = formats::write_table(response_table(response), formats::Format::csv);
  if (!a.valid_out.empty()) write_output(a.valid_out, valid);
  if (!a.response_out.empty()) write_output(a.response_out, curve);
  write_output(a.output, radiance);
  return 0;
}

int run_calibrate(const SeriesArgs& s, const std::string& output) {
  const hdr::ExposureStack stack = read_stack(s.images, s.times);
  const hdr::Response response = recover(stack, s);
  write_output(output, formats::write_table(response_table(response), formats::Format::csv));
  return 0;
}

struct BracketArgs {
  std::string radiance;
  std::vector<std::string> times;
  hdr::CameraModel camera;
  double scale = 1;
  std::uint64_t seed = 1;
  std::string directory;
  std::string response_out;
};

// Simulated camera: writes DIR/e00.png, e01.png, ... (the layout of capture's series).
int run_bracket(const BracketArgs& a) {
  std::vector<double> times;
  for (const std::string& t : a.times) times.push_back(parse_exposure_time(t));
  Image radiance = formats::parse(formats::load_input(a.radiance), formats::read_image);
  if (radiance.pixels.depth() != CV_32F)
    throw bad_input("{}-bit integer image; bracketing needs float radiance (EXR or PFM) ({})",
                    radiance.pixels.depth() == CV_8U ? 8 : 16, a.radiance);
  if (radiance.pixels.channels() == 2 || radiance.pixels.channels() == 4) {
    // Alpha is not light: keep grey or RGB.
    std::vector<cv::Mat> planes;
    cv::split(radiance.pixels, planes);
    planes.pop_back();
    cv::merge(planes, radiance.pixels);
  }
  std::vector<std::string> encoded;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const cv::Mat z = hdr::expose(radiance.pixels * a.scale, times[k], a.camera, a.seed + k);
    encoded.push_back(formats::write_image(Image{z, ColorSpace::srgb}, formats::Format::png));
  }
  std::string curve;
  if (!a.response_out.empty()) {
    hdr::Response r;
    hdr::Curve g{};
    // z = 0 carries no weight anywhere; one step below z = 1 keeps the curve finite.
    g[0] = hdr::model_log_inverse(a.camera, 1) - a.camera.gamma * std::log(2.0);
    for (int z = 1; z < hdr::kCodes; ++z) g[std::size_t(z)] = hdr::model_log_inverse(a.camera, z);
    r.g.assign(std::size_t(radiance.pixels.channels()), g);
    curve = formats::write_table(response_table(r), formats::Format::csv);
  }
  for (std::size_t k = 0; k < encoded.size(); ++k)
    write_output(fmt::format("{}/e{:02}.png", a.directory, k), encoded[k]);
  if (!a.response_out.empty()) write_output(a.response_out, curve);
  return 0;
}

struct SheetArgs {
  std::vector<std::string> images;
  std::string output;
  int columns = 6;
  int width = 160;
};

// A contact sheet of radiance images (e.g. a session's merged EXRs) as one PNG.
int run_sheet(const SheetArgs& a) {
  std::vector<cv::Mat> radiance;
  for (const std::string& path : a.images) {
    const Image image = formats::parse(formats::load_input(path), formats::read_image);
    if (image.pixels.depth() != CV_32F) throw bad_input("not a radiance image (EXR or PFM) ({})", path);
    cv::Mat m = image.pixels;
    if (m.channels() == 4 || m.channels() == 2) {
      std::vector<cv::Mat> planes;
      cv::split(m, planes);
      planes.pop_back();
      cv::merge(planes, m);
    }
    radiance.push_back(m);
  }
  const cv::Mat sheet = hdr::contact_sheet(radiance, a.columns, a.width);
  write_output(a.output, formats::write_image(Image{sheet, ColorSpace::srgb}, formats::Format::png));
  return 0;
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

  MergeArgs merge;
  auto* merge_cmd = app.add_subcommand("merge", "Merge one exposure series into a radiance image (the default)");
  add_series(merge_cmd, merge.series);
  merge_cmd->add_option("-o,--output", merge.output, "Radiance image (.exr or .pfm), - = standard output (EXR)");
  merge_cmd->add_option("--to", merge.to, "Output format: exr or pfm")->check(CLI::IsMember({"exr", "pfm"}));
  merge_cmd->add_flag("--float", merge.full_float, "EXR with 32-bit float channels instead of half");
  merge_cmd->add_option("--response", merge.response_in, "Use this response curve (CSV of hdrmerge calibrate)");
  merge_cmd->add_option("--response-out", merge.response_out, "Also write the response curve used (CSV)");
  merge_cmd->add_option("--valid", merge.valid_out, "Also write the validity map (EXR, fraction of full hat weight)");
  cli::add_threads(*merge_cmd, merge.threads);

  SeriesArgs calibrate;
  std::string calibrate_output = "-";
  auto* calibrate_cmd = app.add_subcommand("calibrate", "Recover the response curve only: CSV z,gR,gG,gB");
  add_series(calibrate_cmd, calibrate);
  calibrate_cmd->add_option("-o,--output", calibrate_output, "Response CSV, - = standard output");

  BracketArgs bracket;
  auto* bracket_cmd = app.add_subcommand("bracket", "Simulated camera: expose a radiance image into 8-bit PNGs DIR/eNN.png");
  bracket_cmd->add_option("radiance", bracket.radiance, "Radiance image (EXR or PFM, grey or RGB)")->required();
  bracket_cmd->add_option("-t,--times", bracket.times, "Exposure times in seconds")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);
  bracket_cmd->add_option("-o,--output", bracket.directory, "Existing folder for e00.png, e01.png, ...")->required();
  bracket_cmd->add_option("--gamma", bracket.camera.gamma, "Response Z = 255 (E t)^(1/gamma)")->check(CLI::PositiveNumber);
  bracket_cmd->add_option("--noise", bracket.camera.noise_dn, "Read noise, standard deviation in DN")
      ->check(CLI::NonNegativeNumber);
  bracket_cmd->add_option("--scale", bracket.scale, "Multiply the radiance first")->check(CLI::PositiveNumber);
  bracket_cmd->add_option("--seed", bracket.seed, "Noise seed (exposure k uses seed + k)");
  bracket_cmd->add_option("--response-out", bracket.response_out, "Also write the true response curve (CSV, g(128) = 0)");

  ManifestArgs session;
  auto* session_cmd = app.add_subcommand(
      "session", "A capture session: merge every (angle, light) set, mask every silhouette, rig JSON on stdout "
                 "(also: hdrmerge --manifest M)");
  session_cmd->add_option("--manifest", session.manifest, "The session's manifest.json, - = standard input")->required();
  session_cmd->add_option("-o,--output", session.output_dir, "Folder for the EXRs and masks (default SESSION/hdr)");
  session_cmd->add_option("--response", session.response_in, "Use this response curve (CSV) instead of recovering one");
  session_cmd->add_option("--method", session.method, "Response recovery: debevec or robertson")
      ->check(CLI::IsMember({"debevec", "robertson"}));
  session_cmd->add_option("--samples", session.samples, "Sample pixels per channel for response recovery")
      ->check(CLI::Range(1, 100000));
  session_cmd->add_option("--lambda", session.lambda, "Smoothness weight of the response")->check(CLI::NonNegativeNumber);
  session_cmd->add_flag("--float", session.full_float, "EXR with 32-bit float channels instead of half");
  cli::add_threads(*session_cmd, session.threads);

  SheetArgs sheet;
  auto* sheet_cmd = app.add_subcommand("sheet", "A contact sheet of radiance images: one exposure for all, sRGB, PNG");
  sheet_cmd->add_option("images", sheet.images, "Radiance images (EXR, PFM)")->required();
  sheet_cmd->add_option("-o,--output", sheet.output, "PNG file, - = standard output")->required();
  sheet_cmd->add_option("--columns", sheet.columns, "Tiles per row")->check(CLI::Range(1, 1000));
  sheet_cmd->add_option("--width", sheet.width, "Tile width in pixels")->check(CLI::Range(8, 10000));

  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See hdrmerge(1).");
  const int n = static_cast<int>(args.size());
  return cli::run(app, n, args.data(), [&] {
    if (merge_cmd->parsed()) return run_merge(merge);
    if (bracket_cmd->parsed()) return run_bracket(bracket);
    if (session_cmd->parsed()) return run_manifest(session);
    if (sheet_cmd->parsed()) return run_sheet(sheet);
    return run_calibrate(calibrate, calibrate_output);
  });
}

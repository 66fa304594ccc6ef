// volwave: wavelet compression of volumes under a stated error bound, and multiscale
// edge maps (docs/volwave.md). Flags only; the subcommands live in cmd_*.cpp.

#include <cmath>
#include <stdexcept>
#include <string>
#include "cli/cli.hpp"
#include "commands.hpp"

namespace {

using namespace fest::volwave_tool;

void add_select(CLI::App* c, InputSelect& s) {
  c->add_option("--field", s.field, "VTI array or frame-stream field to code (a component as name.x)");
  c->add_option("--frame", s.frame, "Frame of a frame stream (from 0)")->check(fest::cli::non_negative);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Wavelet compression of volumes with a guaranteed error bound; multiscale edge maps", "volwave"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  EncodeOptions enc;
  CLI::App* e = app.add_subcommand("encode", "Compress a volume to .vw");
  e->add_option("input", enc.input, "Volume: NIfTI, NRRD, MHA, VTI or a frame stream (- or nothing: standard input)");
  e->add_option("-o,--output", enc.output, "Output .vw (- : standard output)");
  add_select(e, enc.select);
  e->add_option("--max-error", enc.max_error, "L-infinity bound: every voxel within E of the input (checked on decode)");
  e->add_option("--rmse", enc.rmse, "RMS error target (the largest step that stays under it)");
  e->add_flag("--lossless", enc.lossless, "Bit-exact coding (integer wavelets)");
  e->add_option_function<std::string>(
      "--wavelet",
      [&enc](const std::string& w) {
        if (!fest::wavelet::parse_wavelet(w.c_str(), enc.wavelet))
          throw fest::usage_error("--wavelet: unknown wavelet {} (haar, cdf53, cdf97)", w);
      },
      "haar, cdf53 (default) or cdf97 (--rmse only)");
  e->add_option_function<std::string>(
      "--favour",
      [&enc](const std::string& f) {
        if (f == "speed") {
          enc.packed_slack = fest::wavelet::kPackedSlackSpeed;
        } else if (f == "size") {
          enc.packed_slack = 0.0;
        } else {
          std::size_t used = 0;
          double v = 0;
          try {
            v = std::stod(f, &used);
          } catch (const std::exception&) {
            used = 0;
          }
          if (used != f.size() || !std::isfinite(v)) throw fest::usage_error("--favour: speed, size or a slack, not {}", f);
          enc.packed_slack = v;
        }
      },
      "speed (default), size, or a slack S: detail slabs are packed (fastest to decode) when that costs at most "
      "S more bytes than context coding (speed: S = 0.50; size: 0; < 0: never)");
  e->add_option("--levels", enc.levels, "Decomposition levels (default: until no axis exceeds 8; sparse volumes may take 1)")->check(fest::cli::range(0, 16));
  e->add_option("--roi-box", enc.roi_box, "Region x0,y0,z0,x1,y1,z1 (voxel indices, inclusive) coded with --roi-error")
      ->delimiter(',')->expected(6)->allow_extra_args(false)->check(fest::cli::range(0, 2147483647));
  e->add_option("--roi-mask", enc.roi_mask, "Region as a volume: its non-zero voxels are coded with --roi-error");
  e->add_option("--roi-error", enc.roi_error, "L-infinity bound inside the region (at most --max-error)");
  e->add_option("--report", enc.report, "Write sizes, ratio and measured errors as JSON");
  fest::cli::add_threads(*e, enc.threads);
  fest::cli::add_progress(*e, enc.progress);

  DecodeOptions dec;
  CLI::App* d = app.add_subcommand("decode", "Decompress a .vw file (a truncated one to a coarser volume)");
  d->add_option("input", dec.input, ".vw file (- or nothing: standard input)");
  d->add_option("-o,--output", dec.output, "Volume (.nii, .nii.gz, .nrrd, .mha; - : NRRD on standard output)");
  d->add_option("--to", dec.to, "Output format when the name has no extension: nii, nrrd, mha");
  d->add_option("--chunks", dec.chunks, "Decode only the first K chunks (a coarser volume)")->check(fest::cli::range(1, 100));
  d->add_option("--report", dec.report, "Write chunks used and the stated errors as JSON");
  fest::cli::add_threads(*d, dec.threads);
  fest::cli::add_progress(*d, dec.progress);

  InfoOptions inf;
  CLI::App* i = app.add_subcommand("info", "Describe a .vw file as JSON: geometry, bound, chunks and their errors");
  i->add_option("input", inf.input, ".vw file (- or nothing: standard input)");

  EdgesOptions edg;
  CLI::App* g = app.add_subcommand("edges", "Multiscale edge map: wavelet-modulus maxima chained across scales");
  g->add_option("input", edg.input, "Volume (- or nothing: standard input)");
  g->add_option("-o,--output", edg.output, "Edge volume: modulus at edge voxels, 0 elsewhere");
  g->add_option("--to", edg.to, "Output format when the name has no extension: nii, nrrd, mha");
  add_select(g, edg.select);
  g->add_option("--scales", edg.scales, "Dyadic scales 2^1..2^J")->check(fest::cli::range(1, 6));
  g->add_option("--threshold", edg.threshold, "Smallest modulus that counts (default: automatic, from the noise level)");
  g->add_option("--min-scales", edg.min_scales, "Scales a maximum must persist through (default: all)")->check(fest::cli::range(1, 6));
  g->add_option("--points", edg.points, "Also write the sub-voxel edge points as CSV (x,y,z world, modulus, alpha)");
  g->add_option("--report", edg.report, "Write counts and thresholds as JSON");
  fest::cli::add_threads(*g, edg.threads);
  fest::cli::add_progress(*g, edg.progress);

  return fest::cli::run(app, argc, argv, [&] {
    if (*e) {
      enc.quiet = common.quiet;
      return encode_command(enc);
    }
    if (*d) {
      dec.quiet = common.quiet;
      return decode_command(dec);
    }
    if (*i) return info_command(inf);
    return edges_command(edg);
  });
}

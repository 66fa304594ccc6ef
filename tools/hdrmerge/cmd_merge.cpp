// hdrmerge merge: an exposure series merged into one radiance image with the camera's
// response, given or recovered from the series (docs/hdrmerge.md).

#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "hdr/merge.hpp"
#include "response_recovery.hpp"
#include "stack_files.hpp"

namespace fest::hdrmerge_tool {

namespace {

// Where the parts of a merge end on its bar (see run_merge).
constexpr double kReadEnd = 0.3, kResponseEnd = 0.31, kMergeEnd = 0.37;

formats::Format radiance_format(const MergeOptions& a) {
  formats::OutputFormat f{formats::Format::exr, false};
  if (a.to)
    f.format = *a.to;
  else if (!is_stdio(a.output))
    f = formats::output_format_from_path(a.output);
  if (f.gzip || (f.format != formats::Format::exr && f.format != formats::Format::pfm))
    throw usage_error("radiance output must be exr or pfm, not {}", formats::format_name(f.format));
  return f.format;
}

}  // namespace

int run_merge(const MergeOptions& a) {
  const formats::Format format = radiance_format(a);
  const int threads = resolve_threads(a.threads);
  // One bar: the images read, the response, the merge, the encoding; where each ends as
  // measured on seven 6000x3000 exposures (8 s on 2 loaded cores: reading 2.4 s, recovering
  // the response 0.1 s, the merge 0.5 s, encoding a float EXR 5 s, reported by the encoder
  // as lines are written).
  Progress bar("hdrmerge merge", 0, progress_wanted(a.progress));
  auto reached = [&bar](double f) { bar.set(static_cast<std::uint64_t>(1000 * f + 0.5), 1000); };
  const hdr::ExposureStack stack = read_stack(a.series.images, a.series.times, progress_part(bar.callback(), 0.0, kReadEnd));
  const hdr::Response response =
      a.response_in.empty()
          ? recover_response(stack, a.series.method, a.series.samples, a.series.lambda)
          : response_from_table(formats::parse(formats::load_input(a.response_in), formats::read_table));
  reached(kResponseEnd);
  const hdr::MergeResult merged =
      hdr::merge_debevec(stack, response, threads, progress_part(bar.callback(), kResponseEnd, kMergeEnd));
  reached(kMergeEnd);
  formats::ImageWriteOptions w;
  w.exr_half = format == formats::Format::exr && !a.full_float;
  w.progress = progress_part(bar.callback(), kMergeEnd, 1.0);
  // Everything is encoded before anything is written: a failure leaves no file behind.
  const std::string radiance = formats::write_image(Image{merged.radiance, ColorSpace::linear}, format, w);
  std::string valid, curve;
  if (!a.valid_out.empty()) valid = formats::write_image(Image{merged.valid, ColorSpace::linear}, formats::Format::exr, {});
  if (!a.response_out.empty()) curve = formats::write_table(response_table(response), formats::Format::csv);
  if (!a.valid_out.empty()) write_output(a.valid_out, valid);
  if (!a.response_out.empty()) write_output(a.response_out, curve);
  write_output(a.output, radiance);
  bar.finish();
  return 0;
}

}  // namespace fest::hdrmerge_tool

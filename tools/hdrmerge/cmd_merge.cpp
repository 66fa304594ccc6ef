// hdrmerge merge: an exposure series merged into one radiance image with the camera's
// response, given or recovered from the series (docs/hdrmerge.md).

#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "hdr/merge.hpp"
#include "response_recovery.hpp"
#include "stack_files.hpp"

namespace fest::hdrmerge_tool {

namespace {

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
  const hdr::ExposureStack stack = read_stack(a.series.images, a.series.times);
  const hdr::Response response =
      a.response_in.empty()
          ? recover_response(stack, a.series.method, a.series.samples, a.series.lambda)
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

}  // namespace fest::hdrmerge_tool

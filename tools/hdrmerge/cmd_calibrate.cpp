// hdrmerge calibrate: the camera's response recovered from an exposure series (Debevec &
// Malik 1997, or Robertson et al.), written as the CSV table z,gR,gG,gB (docs/hdrmerge.md).

#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "formats/table/table_io.hpp"
#include "response_recovery.hpp"
#include "stack_files.hpp"

namespace fest::hdrmerge_tool {

int run_calibrate(const CalibrateOptions& o) {
  // One bar: the images read, then the recovery (about a fifth of the time).
  Progress bar("hdrmerge calibrate", 0, progress_wanted(o.progress));
  const hdr::ExposureStack stack = read_stack(o.series.images, o.series.times, progress_part(bar.callback(), 0.0, 0.8));
  const hdr::Response response = recover_response(stack, o.series.method, o.series.samples, o.series.lambda);
  bar.finish();
  write_output(o.output, formats::write_table(response_table(response), formats::Format::csv));
  return 0;
}

}  // namespace fest::hdrmerge_tool

// volwave decode (.vw -> volume, possibly from a truncated file).

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "input_location.hpp"
#include "volume_input.hpp"
#include "wavelet/vw_codec.hpp"

namespace fest::volwave_tool {

int decode_command(const DecodeOptions& o) {
  if (o.chunks == 0) throw usage_error("--chunks must be at least 1");
  const std::string bytes = read_input(o.input);
  const Stopwatch watch;
  Progress bar("volwave decode", 0, progress_wanted(o.progress));
  const wavelet::DecodeResult d = named(o.input, [&] { return wavelet::decode_vw(bytes, resolve_threads(o.threads), o.chunks, kMaxVoxels, bar.callback()); });
  bar.finish();
  const double seconds = watch.seconds();
  write_any_volume(d.volume, o.output, o.to);
  if (d.truncated && !o.quiet)
    warn("volwave", fmt::format("truncated file: decoded {} of {} chunks, a coarser volume with max error {} and RMS error {} "
                                "(as the encoder measured them) ({})",
                                d.chunks_decoded, d.chunks_total, d.max_error, d.rmse, where_of(o.input)));
  if (!o.report.empty()) {
    nlohmann::json r = {{"input", o.input},
                        {"dimensions", d.volume.dims},
                        {"chunks_decoded", d.chunks_decoded},
                        {"chunks_total", d.chunks_total},
                        {"truncated", d.truncated},
                        {"max_error", d.max_error},
                        {"rmse", d.rmse},
                        {"decode_seconds", seconds}};
    write_output(o.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::volwave_tool

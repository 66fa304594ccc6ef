// volwave encode: volume -> .vw under an L-infinity bound, an RMS target, or lossless.

#include <cmath>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "volume_input.hpp"
#include "wavelet/vw_codec.hpp"

namespace fest::volwave_tool {

namespace {

std::vector<std::uint8_t> roi_from_box(const Volume& v, const std::vector<long>& box) {
  if (box.size() != 6) throw usage_error("--roi-box needs six numbers x0,y0,z0,x1,y1,z1");
  for (int a = 0; a < 3; ++a) {
    const long lo = box[static_cast<std::size_t>(a)], hi = box[static_cast<std::size_t>(a) + 3];
    if (lo < 0 || hi < lo || hi >= static_cast<long>(v.dims[static_cast<std::size_t>(a)]))
      throw bad_input("region box {}..{} on axis {} is outside the volume's 0..{}", lo, hi, "xyz"[a],
                      v.dims[static_cast<std::size_t>(a)] - 1);
  }
  std::vector<std::uint8_t> mask(v.size(), 0);
  for (long z = box[2]; z <= box[5]; ++z)
    for (long y = box[1]; y <= box[4]; ++y)
      for (long x = box[0]; x <= box[3]; ++x)
        mask[v.index(static_cast<std::size_t>(x), static_cast<std::size_t>(y), static_cast<std::size_t>(z))] = 1;
  return mask;
}

std::vector<std::uint8_t> roi_from_mask(const Volume& v, const std::string& path) {
  const Volume m = read_any_volume(path, {});
  if (m.dims != v.dims)
    throw bad_input("region mask is {}x{}x{}, the volume {}x{}x{} ({})", m.dims[0], m.dims[1], m.dims[2], v.dims[0],
                    v.dims[1], v.dims[2], path);
  std::vector<std::uint8_t> mask(v.size());
  std::size_t inside = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) inside += (mask[i] = (m.voxels[i] != 0 && !std::isnan(m.voxels[i])) ? 1 : 0);
  if (inside == 0) throw bad_input("region mask has no non-zero voxel ({})", path);
  return mask;
}

}  // namespace

int encode_command(const EncodeOptions& o) {
  const int modes = (o.max_error ? 1 : 0) + (o.rmse ? 1 : 0) + (o.lossless ? 1 : 0);
  if (modes != 1) throw usage_error("give exactly one of --max-error, --rmse, --lossless");
  wavelet::EncodeOptions eo;
  eo.wavelet = o.wavelet;
  eo.packed_slack = o.packed_slack;
  if (o.max_error) {
    if (!(*o.max_error > 0) || !std::isfinite(*o.max_error)) throw usage_error("--max-error must be positive, not {}", *o.max_error);
    eo.mode = wavelet::Mode::max_error;
    eo.bound = *o.max_error;
  } else if (o.rmse) {
    if (!(*o.rmse > 0) || !std::isfinite(*o.rmse)) throw usage_error("--rmse must be positive, not {}", *o.rmse);
    eo.mode = wavelet::Mode::rmse;
    eo.bound = *o.rmse;
  } else {
    eo.mode = wavelet::Mode::lossless;
  }
  if (eo.mode != wavelet::Mode::rmse && eo.wavelet == wavelet::Wavelet::cdf97)
    throw usage_error("--wavelet cdf97 is not reversible: use it with --rmse; --max-error and --lossless need haar or cdf53");
  const bool has_roi = !o.roi_box.empty() || !o.roi_mask.empty();
  if (has_roi && !o.max_error) throw usage_error("a region of interest (--roi-box, --roi-mask) needs --max-error");
  if (has_roi != o.roi_error.has_value()) throw usage_error("--roi-error goes with --roi-box or --roi-mask");
  if (!o.roi_box.empty() && !o.roi_mask.empty()) throw usage_error("give --roi-box or --roi-mask, not both");
  if (o.roi_error && (!(*o.roi_error > 0) || *o.roi_error > *o.max_error))
    throw usage_error("--roi-error must be positive and at most --max-error, not {}", *o.roi_error);
  if (o.levels > 16) throw usage_error("--levels: at most 16");
  eo.levels = o.levels;
  eo.threads = resolve_threads(o.threads);

  const Volume v = read_any_volume(o.input, o.select);
  if (!o.roi_box.empty()) eo.roi_mask = roi_from_box(v, o.roi_box);
  if (!o.roi_mask.empty()) eo.roi_mask = roi_from_mask(v, o.roi_mask);
  if (has_roi) eo.roi_bound = *o.roi_error;

  const Stopwatch watch;
  wavelet::EncodeStats st;
  Progress bar("volwave encode", 0, progress_wanted(o.progress));
  eo.progress = bar.callback();
  const std::string bytes = wavelet::encode_vw(v, eo, &st);
  bar.finish();
  const double seconds = watch.seconds();
  write_output(o.output, bytes);
  if (!o.report.empty()) {
    const double raw = static_cast<double>(v.size() * scalar_type_size(v.type));
    nlohmann::json r = {{"input", o.input},
                        {"dimensions", v.dims},
                        {"value_type", scalar_type_name(v.type)},
                        {"mode", wavelet::mode_name(eo.mode)},
                        {"wavelet", wavelet::wavelet_name(eo.wavelet)},
                        {"bound", eo.mode == wavelet::Mode::lossless ? 0.0 : eo.bound},
                        {"bytes", bytes.size()},
                        {"raw_bytes", raw},
                        {"ratio", raw / static_cast<double>(bytes.size())},
                        {"bits_per_voxel", 8.0 * static_cast<double>(bytes.size()) / static_cast<double>(v.size())},
                        {"max_error", st.max_error},
                        {"rmse", st.rmse},
                        {"outliers", st.outliers},
                        {"step", st.step},
                        {"encode_seconds", seconds}};
    if (has_roi) {
      r["roi_bound"] = eo.roi_bound;
      r["roi_max_error"] = st.roi_max_error;
    }
    write_output(o.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::volwave_tool

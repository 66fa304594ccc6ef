// capture run: the acquisition loop over the station's devices into a session folder
// (docs/capture.md §2-3), and --dry-run's plan and time estimate.

#include <atomic>
#include <csignal>
#include <cstdio>

#include "capture/manifest.hpp"
#include "capture/session.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/tool_main.hpp"
#include "formats/table/table_io.hpp"
#include "session_store.hpp"
#include "station_files.hpp"

namespace fest::capture_tool {

using nlohmann::json;

namespace {

std::atomic<bool> interrupted{false};
extern "C" void on_signal(int) { interrupted.store(true); }

// Assumed table speed for --dry-run, which opens no device.
constexpr double kDryRunDegPerS = 30;
constexpr double kPerShotOverheadS = 0.05;  // docs/capture.md §2: <= 50 ms per shot

std::string extension_for(const std::string& format, bool allow_jpeg) {
  if (format == "jpeg") {
    if (!allow_jpeg)
      throw usage_error("the station asks for JPEG, which is lossy and processed in-camera: refused for measurement "
                        "(give --allow-jpeg to override)");
    throw usage_error("JPEG output is not available in this build (camera.format png16, png8 or tiff16)");
  }
  return format == "tiff16" ? ".tiff" : ".png";
}

capture::SessionOptions options_for(const capture::Station& st) {
  capture::SessionOptions o;
  o.motion.approach = st.turntable.approach;
  o.motion.backlash_deg = st.turntable.backlash_deg;
  o.settle_ms = st.turntable.settle_ms;
  o.flush_frames = st.camera.flush_frames;
  o.warmup_ms = [st](const std::string& id) {
    const capture::LightConfig* l = st.light(id);
    return l ? l->warmup_ms : 0u;
  };
  return o;
}

}  // namespace

int run_command(const RunOptions& o) {
  const LoadedStation loaded = load_station(o.station);
  json plan_doc;
  const capture::Plan plan = load_plan(o.plan, &plan_doc);
  const std::string extension = extension_for(loaded.station.camera.format, o.allow_jpeg);
  const std::vector<capture::PlannedShot> shots = capture::expand_plan(plan, loaded.station, extension, o.plan);
  capture::SessionOptions options = options_for(loaded.station);

  if (o.dry_run) {
    json out;
    out["plan"] = capture::plan_to_json(plan);
    out["lights"] = capture::plan_lights(plan, loaded.station);
    out["angles"] = plan.angles_deg.size();
    out["shots"] = shots.size();
    json files = json::array();
    for (const capture::PlannedShot& s : shots) files.push_back(s.file);
    out["files"] = files;
    out["estimate_s"] = capture::estimate_session_s(shots, options, kDryRunDegPerS, kPerShotOverheadS);
    out["estimate_assumes"] = {{"table_deg_per_s", kDryRunDegPerS}, {"overhead_per_shot_s", kPerShotOverheadS}};
    std::fputs(formats::write_json(out).c_str(), stdout);
    return 0;
  }
  if (o.session.empty()) throw usage_error("capture run needs -o SESSION");

  // Canonical plan (counts and brackets expanded) in the journal, so a resume with an
  // equivalent plan file matches.
  const json canonical_plan = capture::plan_to_json(plan);
  SessionStore store(o.session, o.resume, canonical_plan, loaded.station.camera.format,
                     loaded.station.camera.png_compression);
  store.plan = shots;
  store.info.station = loaded.document;

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGHUP, on_signal);
  options.cancel = &interrupted;

  capture::SessionOutcome outcome;
  std::unique_ptr<Devices> devices;
  try {
    devices = std::make_unique<Devices>(open_devices(loaded));
    const capture::CameraInfo cam = devices->camera->info();
    store.info.camera = capture::intrinsics_to_json(devices->intrinsics);
    store.info.camera["name"] = cam.name;
    store.info.camera["bits"] = cam.bits;
    store.info.turntable = {{"steps_per_rev", devices->turntable->info().steps_per_rev},
                            {"cal", capture::turntable_cal_to_json(devices->cal)}};
    store.black_level = devices->black_level;
  } catch (const Error& e) {
    outcome.status = e.status();
    outcome.message = e.what();
    outcome.failed_step = "open devices";
  }
  Progress bar("capture run", shots.size(), progress_wanted(o.progress));
  options.progress = bar.callback();
  if (devices) outcome = capture::run_session(*devices->turntable, *devices->lights, *devices->camera, shots, options, store);

  capture::ManifestInfo info = store.info;
  if (!outcome.complete) {
    store.finish_quietly();  // the pictures already taken are kept
    info.status = "aborted";
    info.failure = {{"step", outcome.failed_step}, {"error", outcome.message}, {"exit_status", int(outcome.status)}};
    store.append({{"abort", info.failure}});
    store.write_manifest(info, shots);
    throw Error(outcome.status, fmt::format("{} (step: {}; {} shots stored, manifest: {}/manifest.json)", outcome.message,
                                            outcome.failed_step, store.kept(), o.session));
  }
  bar.finish();
  const std::string manifest = store.write_manifest(info, shots);
  std::fputs(manifest.c_str(), stdout);
  return 0;
}

}  // namespace fest::capture_tool

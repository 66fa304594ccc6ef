// capture selftest (docs/capture.md §4): open every device, read the turntable's
// info, move +10 and -10 degrees, toggle each light with a dark/lit frame difference
// check, and measure the ambient level with all lights off. A JSON report on standard
// output; exit 1 when a check fails.

#include <cstdio>

#include <opencv2/core.hpp>

#include "capture/turntable.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "formats/table/table_io.hpp"
#include "station_files.hpp"

namespace fest::capture_tool {

using nlohmann::json;

namespace {

// Mean grey level as a fraction of full scale.
double mean_level(const Image& image) {
  const cv::Scalar m = cv::mean(image.pixels);
  const double full = image.pixels.depth() == CV_16U ? 65535.0 : 255.0;
  double sum = 0;
  for (int c = 0; c < image.pixels.channels(); ++c) sum += m[c];
  return sum / image.pixels.channels() / full;
}

}  // namespace

int selftest_command(const SelftestOptions& o) {
  const LoadedStation loaded = load_station(o.station);
  Devices d = open_devices(loaded);
  json report;
  bool ok = true;
  const capture::TurntableInfo info = d.turntable->info();
  report["turntable"] = {{"name", info.name}, {"steps_per_rev", info.steps_per_rev}, {"max_speed", info.max_speed}};
  capture::MotionPolicy policy;
  policy.approach = loaded.station.turntable.approach;
  policy.backlash_deg = loaded.station.turntable.backlash_deg;
  const capture::MoveResult plus = capture::move_to_angle(*d.turntable, 10, policy);
  const capture::MoveResult minus = capture::move_to_angle(*d.turntable, -10, policy);
  const capture::MoveResult back = capture::move_to_angle(*d.turntable, 0, policy);
  const double step_deg = 360.0 / info.steps_per_rev;
  const bool moves_ok = std::abs(plus.angle_deg - 10) <= step_deg && std::abs(minus.angle_deg + 10) <= step_deg &&
                        std::abs(back.angle_deg) <= step_deg;
  ok = ok && moves_ok;
  report["moves"] = {{"plus10_deg", plus.angle_deg}, {"minus10_deg", minus.angle_deg}, {"ok", moves_ok}};

  const capture::CameraInfo cam = d.camera->info();
  report["camera"] = {{"name", cam.name}, {"width", cam.width}, {"height", cam.height}, {"bits", cam.bits}};
  const double exposure = 0.02;
  d.camera->set_exposure(exposure);
  d.lights->all_off();
  const double ambient = mean_level(d.camera->capture());
  report["ambient_level"] = ambient;
  json lights = json::array();
  for (const capture::LightState& l : d.lights->list()) {
    d.lights->only(l.id);
    const double lit = mean_level(d.camera->capture());
    d.lights->all_off();
    // A light that changes the picture by less than 1/1000 of full scale is not seen.
    const bool seen = lit - ambient > 1e-3;
    ok = ok && seen;
    lights.push_back({{"id", l.id}, {"lit_level", lit}, {"ok", seen}});
  }
  report["lights"] = lights;
  report["ok"] = ok;
  std::fputs(formats::write_json(report).c_str(), stdout);
  return ok ? 0 : 1;
}

}  // namespace fest::capture_tool

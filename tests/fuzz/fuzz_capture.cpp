// capture's decoders (lib/capture), every one fed the same bytes: the plan and the station
// files (parse_plan, parse_station, and the expansion of each against a fixed counterpart
// -- the small station and plan of tests/data/capture -- which checks lights, roles and
// on-times), the camera intrinsics and turntable calibration files, the simulated camera's
// scene, the manifest as `hdrmerge session` turns it into a rig (build_rig), the session
// journal (replay_journal), the device URIs and the simulated turntable's options, and
// the TTP/1 turntable's GET_INFO / GET_STATUS replies. Each must give its type or a clean
// fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/calib_board.hpp"
#include "capture/device_uri.hpp"
#include "capture/manifest.hpp"
#include "capture/plan.hpp"
#include "capture/rig.hpp"
#include "capture/sim_camera.hpp"
#include "capture/sim_turntable.hpp"
#include "capture/station.hpp"
#include "capture/ttp1.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;

const Station& fixed_station() {
  static const Station s = parse_station(nlohmann::json::parse(R"({
    "camera": {"uri": "sim:small_scene.json", "format": "png16"},
    "turntable": {"uri": "sim:steps=51200,speed=90", "approach": "ccw", "backlash_deg": 2.0, "settle_ms": 500},
    "lights": [{"id": "L0", "uri": "sim:", "position_mm": [300.0, -250.0, 200.0], "intensity": [1.0, 0.97, 0.91],
                "warmup_ms": 300, "max_on_s": 120},
               {"id": "BG", "uri": "sim:", "role": "backlight"}]})"), "station");
  return s;
}

const Plan& fixed_plan() {
  static const Plan p = parse_plan(nlohmann::json::parse(R"({"angles_deg": {"count": 4}, "lights": ["L0"],
    "exposures_s": {"base": 0.001, "stops": 1, "count": 3},
    "per_view": {"silhouette": {"lights_on": ["BG"], "exposure_s": 0.01}}})"), "plan");
  return p;
}

// Shots an expansion would make, to keep the target's memory bounded: a plan of 100000
// angles x 64 exposures x 100 takes is legal and expands to hundreds of millions of shots.
double shots_of(const Plan& p, std::size_t lights) {
  return static_cast<double>(p.angles_deg.size()) * (static_cast<double>(p.exposures_s.size()) * p.repeat * (lights + 1) + 4 +
                                                     p.lightcal.count + p.dark.count);
}

template <class F>
void clean(F&& f) {
  try {
    f();
  } catch (const fest::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::vector<std::uint8_t> raw(data, data + size);
  clean([&] { ttp1::decode_info(raw); });
  clean([&] { ttp1::decode_status(raw); });
  clean([&] { replay_journal(bytes, "journal"); });
  if (size <= 256) {  // a station's device URIs (usage_error for a bad one: they may come from flags)
    const std::string uri(bytes);
    clean([&] { parse_device_uri(uri); });
    clean([&] { parse_sim_turntable_uri(uri); });
    clean([&] { parse_board_spec(uri); });  // --board COLSxROWSxSIZE[unit]
  }
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
  if (doc.is_discarded()) return 0;
  clean([&] {
    const Plan p = parse_plan(doc, "plan");
    (void)plan_to_json(p);
    if (shots_of(p, fixed_station().lights.size()) <= 20000) expand_plan(p, fixed_station(), ".png", "plan");
  });
  clean([&] {
    const Station s = parse_station(doc, "station");
    if (shots_of(fixed_plan(), s.lights.size()) <= 20000) {
      expand_plan(fixed_plan(), s, ".png", "plan");
      plan_lights(fixed_plan(), s);
    }
  });
  clean([&] { parse_intrinsics(doc, "camera.json"); });
  clean([&] { parse_turntable_cal(doc, "turntable.json"); });
  clean([&] { parse_sim_scene(doc, "scene.json"); });
  clean([&] { shot_from_json(doc, "journal", "shot"); });
  clean([&] {
    std::vector<RigImage> images(2);
    images[0].file = "a000_L0.exr";
    images[0].light = "L0";
    images[1].file = "a001.exr";
    images[1].angle_index = 1;
    images[1].angle_deg = 90;
    build_rig(doc, images, "session", "manifest.json");
  });
  return 0;
}

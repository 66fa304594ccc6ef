#include "station_files.hpp"

#include <cstdlib>
#include <filesystem>

#include "capture/device_uri.hpp"
#include "capture/sim_camera.hpp"
#include "capture/sim_turntable.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "devices/exec_camera.hpp"
#include "devices/open_devices.hpp"
#include "devices/v4l2_camera.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json_file(const std::string& path) {
  const std::string text = read_input(path);
  try {
    return formats::read_json(text);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), path));
  }
}

std::string resolve(const std::string& folder, const std::string& name) {
  const fs::path p(name);
  return p.is_absolute() || folder.empty() ? name : (fs::path(folder) / p).string();
}

}  // namespace

LoadedStation load_station(const std::string& path_flag) {
  std::string path = path_flag;
  if (path.empty()) {
    const char* env = std::getenv("CAPTURE_STATION");
    if (env && *env) path = env;
  }
  if (path.empty()) throw usage_error("no station: give --station FILE or set CAPTURE_STATION");
  LoadedStation s;
  s.path = path;
  s.folder = is_stdio(path) ? "" : fs::path(path).parent_path().string();
  s.document = read_json_file(path);
  s.station = capture::parse_station(s.document, path);
  if (!s.station.camera.intrinsics_file.empty()) {
    const std::string f = resolve(s.folder, s.station.camera.intrinsics_file);
    s.station.camera.intrinsics = capture::parse_intrinsics(read_json_file(f), f);
  }
  if (!s.station.turntable.calibration_file.empty()) {
    const std::string f = resolve(s.folder, s.station.turntable.calibration_file);
    s.station.turntable.calibration = capture::parse_turntable_cal(read_json_file(f), f);
  }
  return s;
}

capture::Plan load_plan(const std::string& path, json* document) {
  const json doc = read_json_file(path);
  if (document) *document = doc;
  return capture::parse_plan(doc, path);
}

Devices open_devices(const LoadedStation& loaded) {
  const capture::Station& st = loaded.station;
  Devices d;
  // Turntables and lights: sim:, usb:, gpio-stepper:, gpio:, usb-aux: (devices/).
  d.turntable = devices::open_turntable(st.turntable.uri);
  std::vector<devices::LightConfig> configs;
  for (const capture::LightConfig& l : st.lights) configs.push_back({l.id, l.uri, l.active_low});
  std::unique_ptr<capture::LightBank> lights = devices::open_lights(configs);

  const capture::DeviceUri camera_uri = capture::parse_device_uri(st.camera.uri);
  d.cal = st.turntable.calibration ? *st.turntable.calibration : capture::default_turntable_cal();
  if (camera_uri.scheme == "exec" || camera_uri.scheme == "v4l2") {
    std::unique_ptr<capture::Camera> camera;
    if (camera_uri.scheme == "exec") camera = std::make_unique<devices::ExecCamera>(camera_uri.path);
    else camera = std::make_unique<devices::V4l2Camera>(st.camera.uri);
    // Without intrinsics the default ones need the size: a V4L2 camera knows it from the
    // format it negotiated; an exec: camera once a picture was taken, so take one.
    const capture::CameraInfo info = camera->info();
    if (st.camera.intrinsics) d.intrinsics = *st.camera.intrinsics;
    else if (info.width > 0 && info.height > 0) d.intrinsics = capture::default_intrinsics(info.width, info.height);
    else {
      const Image first = camera->capture();
      d.intrinsics = capture::default_intrinsics(first.pixels.cols, first.pixels.rows);
    }
    d.camera = std::move(camera);
    d.lights = std::move(lights);
    return d;
  }
  if (camera_uri.scheme != "sim")
    throw usage_error("camera {}: unknown scheme '{}' (sim:, v4l2:, exec:)", st.camera.uri, camera_uri.scheme);
  camera_uri.expect_only({});
  capture::SimScene scene = capture::default_sim_scene();
  if (!camera_uri.path.empty()) {
    const std::string f = resolve(loaded.folder, camera_uri.path);
    scene = capture::parse_sim_scene(read_json_file(f), f);
  }
  d.intrinsics = st.camera.intrinsics ? *st.camera.intrinsics : capture::default_intrinsics(scene.width, scene.height);
  d.black_level = scene.response.black_level;
  d.camera = std::make_unique<capture::SimCamera>(scene, d.intrinsics, d.cal, st, *d.turntable, *lights);
  d.lights = std::move(lights);
  return d;
}

}  // namespace fest::capture_tool

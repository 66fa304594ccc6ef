#pragma once
// capture's side of the files: station.json with the calibrations it names (paths
// relative to the station file), plan.json, and the devices the station's URIs name.

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "capture/camera.hpp"
#include "capture/light_bank.hpp"
#include "capture/plan.hpp"
#include "capture/station.hpp"
#include "capture/turntable.hpp"

namespace fest::capture_tool {

struct LoadedStation {
  capture::Station station;
  nlohmann::json document;  // as given
  std::string path, folder;  // folder: where relative names are resolved
};

// Reads the station (path, or $CAPTURE_STATION when empty) and the calibration files it
// names. Throws usage_error when neither is given, io/bad_input for the files.
LoadedStation load_station(const std::string& path);
capture::Plan load_plan(const std::string& path, nlohmann::json* document = nullptr);

struct Devices {
  std::unique_ptr<capture::Turntable> turntable;
  std::unique_ptr<capture::LightBank> lights;
  std::unique_ptr<capture::Camera> camera;
  capture::CameraIntrinsics intrinsics;  // the station's, or the defaults for the camera's size
  capture::TurntableCal cal;             // the station's, or the default pose
  double black_level = 0;
};

// Opens the station's devices: turntable and lights through devices/open_devices (usb:,
// gpio-stepper:, gpio:, usb-aux:, sim:), the camera here: sim:[scene.json] (relative to
// the station), v4l2:, exec:.
Devices open_devices(const LoadedStation& station);

}  // namespace fest::capture_tool

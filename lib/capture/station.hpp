#pragma once
// The station description, station.json (fest-capture(5)): which devices, where the
// lights are, how the turntable approaches its targets, and the calibrations (camera
// intrinsics, turntable pose R_T0, t_T0 of docs/capture.md §1). Parsed from JSON without I/O: a
// calibration given as a file name is left for the tool to read and hand to
// parse_intrinsics / parse_turntable_cal. Lengths are millimetres.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "capture/turntable.hpp"

namespace fest::capture {

// brdffit's cam.json fields (brdffit(1)), without the pose.
struct CameraIntrinsics {
  std::array<double, 9> K{};    // row-major fx 0 cx / 0 fy cy / 0 0 1, pixels
  std::array<double, 5> dist{};  // k1 k2 p1 p2 k3 (OpenCV)
  int width = 0, height = 0;
};

// The pose of the turntable frame T at angle 0 in the camera frame C (docs/capture.md §1):
// X_C = R_T0 Rz(theta) X_T + t_T0.
struct TurntableCal {
  std::array<double, 9> R_T0{};  // row-major
  std::array<double, 3> t_T0{};  // mm
};

struct CameraConfig {
  std::string uri;
  std::string intrinsics_file;                  // "intrinsics": "camera.json"
  std::optional<CameraIntrinsics> intrinsics;   // inline, or once the file was read
  int flush_frames = 0;                         // frames discarded after an exposure change
  std::string format = "png16";                 // png16, png8, tiff16, jpeg
  int png_compression = 1;                      // zlib level; 0 stores: fastest, twice the disk
};

struct TurntableConfig {
  std::string uri;
  std::string calibration_file;
  std::optional<TurntableCal> calibration;
  Approach approach = Approach::ccw;
  double backlash_deg = 2.0;
  unsigned settle_ms = 500;
  bool require_homed = false;
};

struct LightConfig {
  std::string id;
  std::string uri;
  bool active_low = false;
  std::optional<std::array<double, 3>> position_mm;  // in the camera frame C
  std::array<double, 3> intensity{1, 1, 1};
  std::string role = "light";  // "light" or "backlight" (silhouettes)
  unsigned warmup_ms = 0;
  double max_on_s = 0;  // 0 = no limit
};

struct Station {
  CameraConfig camera;
  TurntableConfig turntable;
  std::vector<LightConfig> lights;

  const LightConfig* light(const std::string& id) const;
};

// Throws bad_input naming `where` and the JSON path for unknown keys and bad values.
Station parse_station(const nlohmann::json& doc, const std::string& where);
// A camera.json (cam.json fields; other keys such as a calibration's "rms" are kept out).
CameraIntrinsics parse_intrinsics(const nlohmann::json& doc, const std::string& where);
// A turntable_cal.json: "R_T0" (9 numbers or 3 rows) and "t_T0" (mm); other keys ignored.
TurntableCal parse_turntable_cal(const nlohmann::json& doc, const std::string& where);

// Defaults when a station has no calibration. The camera: focal length 1000 px per 640 px
// of width, principal point in the middle, no distortion. The table: 500 mm in front of
// the camera, its top 60 mm below the optical axis, its axis pointing up in the image
// (T's z = C's -y), T's x = C's x.
CameraIntrinsics default_intrinsics(int width, int height);
TurntableCal default_turntable_cal();

nlohmann::json intrinsics_to_json(const CameraIntrinsics& k);
nlohmann::json turntable_cal_to_json(const TurntableCal& cal);

}  // namespace fest::capture

#pragma once
// camera.json <-> CameraModel: the file `capture calib-camera` writes ({"K": 9 numbers
// row-major, "dist": up to 5 numbers, "width", "height", ...}; man capture-calib(1)).
// Other fields (R, t, rms, views) are allowed and ignored: the camera is the reference
// frame of the poses.

#include <string>
#include <string_view>

#include "markers/camera_model.hpp"

namespace fest::markers {

// Throws fest::Error (bad_input) with "camera: ..." messages for anything malformed:
// not JSON, missing K, width or height, non-positive focal lengths, K[8] != 1.
CameraModel decode_camera_json(std::string_view text);

// The same fields back (K, dist, width, height; R = I and t = 0).
std::string encode_camera_json(const CameraModel& camera);

}  // namespace fest::markers

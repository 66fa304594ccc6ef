#pragma once
// The camera every backend implements (docs/capture.md §4): set an exposure time, take
// a picture. Pictures are fest::Image (8- or 16-bit, 1 or 3 channels, R,G,B order).

#include <string>

#include "core/image.hpp"

namespace fest::capture {

struct CameraInfo {
  int width = 0, height = 0;
  int channels = 3;
  int bits = 16;  // 8 or 16: the depth capture() returns
  std::string name;
};

// Backends throw fest::Error with the device exit statuses (README "Conventions"): device_not_found (5),
// device_error (6), timeout (7, the camera did not deliver), permission (8).
class Camera {
 public:
  virtual ~Camera() = default;
  virtual CameraInfo info() = 0;
  virtual void set_exposure(double seconds) = 0;
  virtual Image capture() = 0;
  // Which take of one exposure the next picture is (the plan's "repeat"): a simulator
  // draws fresh noise for each take; a real camera has no use for it.
  virtual void set_repeat_index(int /*take*/) {}
};

}  // namespace fest::capture

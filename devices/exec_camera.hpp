#pragma once
// A camera driven by an external command (URI `exec:CMD-TEMPLATE`, docs/capture.md
// §4), e.g. the gphoto2 CLI for DSLRs:
//   exec:gphoto2 --set-config shutterspeed={shutter} --capture-image-and-download --filename {out}
// Placeholders: {out} (the file the command must write), {exposure_s} (seconds),
// {shutter} (1/250 style below 1 s, else seconds), {iso} (empty: no ISO control here),
// {index} (0-based picture number). The command runs through /bin/sh; the picture is read
// back through formats/ (PNG, TIFF, PNM; 8 or 16-bit) and the temporary file removed.

#include <string>

#include "capture/camera.hpp"

namespace fest::devices {

class ExecCamera : public capture::Camera {
 public:
  // `command` is the URI without "exec:". timeout_s: the command is killed after it.
  explicit ExecCamera(std::string command, double timeout_s = 60);
  capture::CameraInfo info() override;
  void set_exposure(double seconds) override;
  Image capture() override;

  // The command line for one picture (placeholders replaced; {out} shell-quoted).
  std::string expand(const std::string& out_path) const;

 private:
  std::string command_;
  double timeout_s_;
  double exposure_s_ = 0.01;
  int index_ = 0;
  capture::CameraInfo info_;
};

}  // namespace fest::devices

#pragma once
// turntable's subcommands (docs/turntable.md), each taking its typed
// options. main.cpp fills these from flags; everything else in this folder is the
// fest_turntable_app library.

#include <string>

namespace fest::turntable_tool {

// Which device to drive and how to print: shared by every subcommand.
struct DeviceOptions {
  std::string device;   // URI; empty: the station's turntable.uri, else usb:
  std::string station;  // station.json (empty: $CAPTURE_STATION)
  bool json = false;    // one JSON object instead of text
  bool quiet = false;   // no warnings
};

// The final direction of a move.
enum class Approach { ccw, cw, shortest };

struct HomeOptions {
  double timeout_s = 60;
  bool clockwise = false;
  double speed_deg_s = 0;  // 0: the device's default
};

struct MoveOptions {
  double degrees = 0;
  bool relative = false;
  bool no_wait = false;
  double speed_deg_s = 0;  // 0: the device's maximum
  Approach approach = Approach::ccw;
  double backlash_deg = 2.0;
  int settle_ms = 500;
};

int list_command(const DeviceOptions& d);
int info_command(const DeviceOptions& d);
int status_command(const DeviceOptions& d);
int home_command(const DeviceOptions& d, const HomeOptions& o);
int move_command(const DeviceOptions& d, const MoveOptions& o);
int stop_command(const DeviceOptions& d, bool now);
int zero_command(const DeviceOptions& d);
int enable_command(const DeviceOptions& d, bool enable);

}  // namespace fest::turntable_tool

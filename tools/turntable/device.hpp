#pragma once
// What every turntable subcommand shares: the device URI from --device or the station
// file, the open device (with the jitter warning of a host-generated step train), the
// status as JSON, and printing text or JSON.

#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "capture/turntable.hpp"
#include "commands.hpp"

namespace fest::turntable_tool {

// --device, else the station's turntable.uri, else the TTP/1 default.
std::string device_uri(const DeviceOptions& d);

// The device of `d`, open for one subcommand. Closing it after a subcommand that worked
// warns when a GPIO step train runs without real-time priority (docs/turntable.md §3);
// a failure keeps its one diagnostic line.
class OpenTurntable {
 public:
  explicit OpenTurntable(const DeviceOptions& d);
  ~OpenTurntable();
  OpenTurntable(const OpenTurntable&) = delete;
  OpenTurntable& operator=(const OpenTurntable&) = delete;
  capture::Turntable& operator*() const { return *t_; }
  capture::Turntable* operator->() const { return t_.get(); }

 private:
  std::unique_ptr<capture::Turntable> t_;
  bool quiet_;
};

// Prints `j` on one line with --json, else `text`.
void print(const DeviceOptions& d, const nlohmann::json& j, const std::string& text);

const char* state_name(capture::MotionState s);
nlohmann::json status_json(const capture::TurntableStatus& s, std::uint32_t spr);

// deg/s -> steps/s; 0 stays 0 (the device's default or maximum).
std::uint32_t speed_steps(double deg_s, std::uint32_t spr);

}  // namespace fest::turntable_tool

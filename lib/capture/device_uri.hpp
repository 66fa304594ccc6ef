#pragma once
// Device URIs of docs/capture.md §4, one string per device:
//   scheme:[path][,key=value,...]     e.g. usb:1209:0001#SN42, gpio:chip=gpiochip0,line=17,
//   sim:speed=90,backlash=0.2, v4l2:/dev/video0,fourcc=Y16
// The part before the first ',' that is not key=value is the path (usb's VID:PID#SERIAL,
// v4l2's device node); the rest are options in the order given. Parsing only splits; each
// backend checks its own keys, so an unknown key is reported by the backend that owns it.

#include <string>
#include <utility>
#include <vector>

namespace fest::capture {

struct DeviceUri {
  std::string scheme;  // "usb", "gpio", "gpio-stepper", "sim", "v4l2", "exec", ...
  std::string path;    // may be empty
  std::vector<std::pair<std::string, std::string>> options;

  // The value of key, or fallback when absent.
  std::string get(const std::string& key, const std::string& fallback = "") const;
  bool has(const std::string& key) const;
  // usage_error naming the first key not in `known` (with the scheme in the message).
  void expect_only(const std::vector<std::string>& known) const;
};

// One item of a comma-separated option list: "key=value", or a bare "flag" (has_value
// false, value empty). Backends whose URIs take bare flags (active_low) read these.
struct DeviceOption {
  std::string item;  // as written, for messages
  std::string key, value;
  bool has_value = false;
};
std::vector<DeviceOption> split_device_options(const std::string& list);

// usage_error for a URI without a scheme ("gpiochip0") or an empty key ("sim:=3").
// exec: URIs keep everything after "exec:" as the path (command templates contain commas).
DeviceUri parse_device_uri(const std::string& uri);

}  // namespace fest::capture

// lights list: id,uri,state of every light as CSV, looking without requesting (requesting
// a GPIO output would switch it).

#include <cstdio>

#include "commands.hpp"
#include "core/error.hpp"
#include "devices/gpio_lights.hpp"
#include "devices/usb_aux_lights.hpp"
#include "station.hpp"

namespace fest::lights_tool {

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

int list_command(const StationOptions& s) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  std::string text = "id,uri,state\n";
  for (const devices::LightConfig& l : lights) {
    const std::string scheme = l.uri.substr(0, l.uri.find(':'));
    std::string state;
    if (scheme == "gpio") {
      devices::GpioLineRef ref = devices::parse_gpio_uri(l.uri);
      state = devices::probe_gpio_line(ref);
    } else if (scheme == "sim") {
      state = "off";
    } else if (scheme == "usb-aux") {
      devices::parse_usb_aux_uri(l.uri);
      state = "unknown";  // TTP/1 has no request that reads the aux outputs back
    } else {
      throw usage_error("light {}: URI scheme '{}:' is not supported by this build (gpio:, usb-aux:, sim:)", l.id, scheme);
    }
    text += csv_field(l.id) + "," + csv_field(l.uri) + "," + csv_field(state) + "\n";
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace fest::lights_tool

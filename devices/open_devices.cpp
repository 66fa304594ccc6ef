#include "devices/open_devices.hpp"

#include <algorithm>

#include "capture/device_uri.hpp"
#include "capture/sim_lights.hpp"
#include "capture/sim_turntable.hpp"
#include "core/error.hpp"
#include "devices/gpio_lights.hpp"
#include "devices/gpio_stepper.hpp"
#include "devices/usb_aux_lights.hpp"
#include "devices/usb_turntable.hpp"

namespace fest::devices {
namespace {

// The scheme only: gpio: URIs have a bare ",active_low" flag that the generic URI
// parser rejects, so each backend parses its own URIs.
std::string scheme_of(const std::string& uri) {
  const std::size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0) return capture::parse_device_uri(uri).scheme;  // reports the error
  return uri.substr(0, colon);
}

}  // namespace

std::unique_ptr<capture::Turntable> open_turntable(const std::string& uri) {
  const capture::DeviceUri d = capture::parse_device_uri(uri.rfind("gpio-stepper:", 0) == 0 ? "gpio-stepper:" : uri);
  if (d.scheme == "usb") return std::make_unique<UsbTurntable>(parse_usb_uri(uri));
  if (d.scheme == "gpio-stepper") return std::make_unique<GpioStepper>(parse_gpio_stepper_uri(uri));
  if (d.scheme == "sim") return std::make_unique<capture::SimTurntable>(capture::parse_sim_turntable_uri(uri));
  throw usage_error("turntable URI scheme '{}:' is not supported by this build (usb:, gpio-stepper:, sim:)", d.scheme);
}

std::unique_ptr<capture::LightBank> open_lights(const std::vector<LightConfig>& lights) {
  return open_lights(lights, {});
}

std::unique_ptr<capture::LightBank> open_lights(const std::vector<LightConfig>& lights,
                                                const std::vector<std::string>& initially_on) {
  if (lights.empty()) throw usage_error("no lights to open (the station's \"lights\" array is empty)");
  std::string kind;
  for (const LightConfig& l : lights) {
    const std::string scheme = scheme_of(l.uri);
    if (scheme != "gpio" && scheme != "sim" && scheme != "usb-aux")
      throw usage_error("light {}: URI scheme '{}:' is not supported by this build (gpio:, usb-aux:, sim:)", l.id, scheme);
    if (!kind.empty() && scheme != kind)
      throw usage_error("light {} is {}: but light {} is {}: -- one bank must be all gpio:, all usb-aux: or all sim:", l.id,
                        scheme, lights.front().id, kind);
    kind = scheme;
  }
  for (const std::string& id : initially_on)
    if (std::none_of(lights.begin(), lights.end(), [&](const LightConfig& l) { return l.id == id; }))
      throw usage_error("no light '{}' in the station", id);
  const auto lit = [&](const std::string& id) {
    return std::find(initially_on.begin(), initially_on.end(), id) != initially_on.end();
  };
  if (kind == "sim") {
    std::vector<std::string> ids;
    for (const LightConfig& l : lights) {
      const capture::DeviceUri d = capture::parse_device_uri(l.uri);
      if (!d.path.empty() || !d.options.empty()) throw usage_error("light {}: a simulated light takes no options ({})", l.id, l.uri);
      ids.push_back(l.id);
    }
    auto bank = std::make_unique<capture::SimLightBank>(ids);
    for (const LightConfig& l : lights)
      if (lit(l.id)) bank->set(l.id, true);
    return bank;
  }
  if (kind == "usb-aux") {
    std::vector<UsbAuxLightSpec> specs;
    for (const LightConfig& l : lights) {
      if (l.active_low) throw usage_error("light {}: active_low has no meaning for a usb-aux light", l.id);
      specs.push_back({l.id, parse_usb_aux_uri(l.uri), lit(l.id)});
    }
    return std::make_unique<UsbAuxLightBank>(specs);
  }
  std::vector<GpioLightSpec> specs;
  for (const LightConfig& l : lights) {
    GpioLightSpec s;
    s.id = l.id;
    s.ref = parse_gpio_uri(l.uri);
    s.ref.active_low = s.ref.active_low || l.active_low;
    s.initial_on = lit(l.id);
    specs.push_back(s);
  }
  return std::make_unique<GpioLightBank>(specs);
}

}  // namespace fest::devices

#pragma once
// Device URI -> backend, for every tool that drives a station (turntable, lights,
// capture). docs/capture.md §4 lists the URIs.
//
//   open_turntable("usb:1209:0001#SN7")  TTP/1 over libusb       (devices/usb_turntable)
//   open_turntable("gpio-stepper:chip=gpiochip0,step=17,dir=27,steps=3200")  (devices/gpio_stepper)
//   open_turntable("sim:speed=90")       in-process simulator    (lib/capture/sim_turntable)
//   open_lights({{"L0", "gpio:chip=gpiochip0,line=GPIO17", false}, ...})
//   open_lights({{"L0", "usb-aux:0", false}, ...})    aux outputs of a TTP/1 controller
//   open_lights({{"L0", "sim:", false}, ...})
//
// Errors are fest::Error with the README's exit statuses ("Conventions": 2 for a bad URI, 5-8 from devices).

#include <memory>
#include <string>
#include <vector>

#include "capture/light_bank.hpp"
#include "capture/turntable.hpp"

namespace fest::devices {

// One entry of a station's "lights" array (the keys a backend needs).
struct LightConfig {
  std::string id;
  std::string uri;          // "gpio:chip=...,line=...", "usb-aux:N" or "sim:"
  bool active_low = false;  // or ",active_low" in the URI
};

// usb: (TTP/1 over libusb), gpio-stepper: (step/dir driver on GPIO lines), sim:;
// usage_error for other schemes.
std::unique_ptr<capture::Turntable> open_turntable(const std::string& uri);

// All lights of one bank must be of one kind, all gpio:, all usb-aux: (one controller)
// or all sim: (a usage_error otherwise). Every light starts off.
std::unique_ptr<capture::LightBank> open_lights(const std::vector<LightConfig>& lights);

// The same, with the lights named in `initially_on` requested lit (no off->on glitch for
// one-shot commands such as `lights on L0`).
std::unique_ptr<capture::LightBank> open_lights(const std::vector<LightConfig>& lights,
                                                const std::vector<std::string>& initially_on);

}  // namespace fest::devices

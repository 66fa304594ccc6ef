#pragma once
// libgpiod v1 helpers shared by the GPIO backends (lights, step/dir stepper): chip and
// line lookup and requests, with errno mapped to the device exit statuses 5-8 (README "Conventions"). Internal
// to devices/.

#include <string>

#include <gpiod.h>

#include "devices/gpio_lights.hpp"

namespace fest::devices::gpio {

// ENOENT/ENODEV -> device_not_found (5), EACCES/EPERM -> permission (8) naming the gpio
// group and udev rule, anything else -> device_error (6).
[[noreturn]] void throw_errno(int err, const std::string& what, const std::string& where);
gpiod_chip* open_chip(const std::string& chip);
gpiod_line* find_line(gpiod_chip* chip, const GpioLineRef& ref);
std::string consumer_of(gpiod_line* line);
// "gpiochip0 line 17 (GPIO17)"
std::string describe(const GpioLineRef& ref, gpiod_line* line);
// Requests an output with consumer "capture"; EBUSY -> device_error naming the holder.
void request_output(gpiod_line* line, const std::string& who, bool active_low, bool initial, const std::string& where);

}  // namespace fest::devices::gpio

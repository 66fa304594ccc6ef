#pragma once
// Lights on GPIO output lines through libgpiod 1.6 (uAPI v1), docs/lights.md §3:
//
//   gpio:chip=gpiochip0,line=GPIO17[,active_low]     line by name or by offset ("17")
//
// Every line is requested (consumer "capture") for as long as the bank lives, because
// the kernel only guarantees an output's value while it is requested; the destructor
// switches every light off before releasing, unless keep_state_on_release() was called.
// Errors: missing chip or line -> 5; line busy -> 6 naming the consumer that holds it;
// EACCES on /dev/gpiochipN -> 8 naming the gpio group and udev rule.

#include <memory>
#include <string>
#include <vector>

#include "capture/light_bank.hpp"

struct gpiod_chip;
struct gpiod_line;

namespace fest::devices {

struct GpioLineRef {
  std::string chip = "gpiochip0";  // a name under /dev, or an absolute path
  std::string line;                // a line name ("GPIO17") or an offset ("17")
  bool active_low = false;
};

// Parses "gpio:chip=...,line=...[,active_low]"; usage_error for anything else.
GpioLineRef parse_gpio_uri(const std::string& uri);

struct GpioLightSpec {
  std::string id;
  GpioLineRef ref;
  bool initial_on = false;  // the value the line is requested with
};

class GpioLightBank : public capture::LightBank {
 public:
  explicit GpioLightBank(const std::vector<GpioLightSpec>& lights);
  ~GpioLightBank() override;
  GpioLightBank(const GpioLightBank&) = delete;
  GpioLightBank& operator=(const GpioLightBank&) = delete;

  std::vector<capture::LightState> list() override;
  void set(const std::string& id, bool on) override;
  void all_off() override;
  void keep_state_on_release() override { keep_ = true; }

 private:
  struct Light {
    std::string id;
    std::string where;  // "gpiochip0 line 17 (GPIO17)" for messages
    gpiod_line* line = nullptr;
    bool on = false;
  };
  struct Chip {
    std::string name;
    gpiod_chip* chip = nullptr;
  };
  void release() noexcept;
  std::vector<Chip> chips_;
  std::vector<Light> lights_;
  bool keep_ = false;
};

// Whether a light's line exists and who uses it, without requesting it (for
// `lights list`): "free" or "used by CONSUMER". Errors as the bank's.
std::string probe_gpio_line(const GpioLineRef& ref);

}  // namespace fest::devices

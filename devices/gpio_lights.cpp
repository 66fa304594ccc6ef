#include "devices/gpio_lights.hpp"

#include <gpiod.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "capture/device_uri.hpp"
#include "core/error.hpp"
#include "devices/gpio_util.hpp"

namespace fest::devices {
namespace gpio {

const char* const kGpioHint =
    "add your user to the gpio group, or give the chip to a group with a udev rule such as "
    "SUBSYSTEM==\"gpio\", KERNEL==\"gpiochip*\", GROUP=\"gpio\", MODE=\"0660\"";

bool is_offset(const std::string& s) {
  return !s.empty() && s.size() < 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string chip_path(const std::string& chip) { return chip.rfind('/', 0) == 0 ? chip : "/dev/" + chip; }

[[noreturn]] void throw_errno(int err, const std::string& what, const std::string& where) {
  switch (err) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
      throw make_error(Status::device_not_found, "{}: {} ({})", what, std::strerror(err), where);
    case EACCES:
    case EPERM:
      throw make_error(Status::permission, "{}: permission denied: {} ({})", what, kGpioHint, where);
    default:
      throw make_error(Status::device_error, "{}: {} ({})", what, std::strerror(err), where);
  }
}

gpiod_chip* open_chip(const std::string& chip) {
  errno = 0;
  gpiod_chip* c = gpiod_chip_open(chip_path(chip).c_str());
  if (!c) {
    const int err = errno ? errno : ENODEV;
    if (err == ENOENT) throw make_error(Status::device_not_found, "no GPIO chip {} ({} does not exist)", chip, chip_path(chip));
    throw_errno(err, "cannot open GPIO chip " + chip, chip_path(chip));
  }
  return c;
}

gpiod_line* find_line(gpiod_chip* chip, const GpioLineRef& ref) {
  errno = 0;
  if (is_offset(ref.line)) {
    const unsigned offset = unsigned(std::stoul(ref.line));
    if (offset >= gpiod_chip_num_lines(chip))
      throw make_error(Status::device_not_found, "{} has no line {} (it has {} lines)", ref.chip, offset, gpiod_chip_num_lines(chip));
    gpiod_line* l = gpiod_chip_get_line(chip, offset);
    if (!l) throw_errno(errno, "cannot read line " + ref.line, ref.chip);
    return l;
  }
  gpiod_line* l = gpiod_chip_find_line(chip, ref.line.c_str());
  if (!l) {
    if (errno == 0 || errno == ENOENT) throw make_error(Status::device_not_found, "{} has no line named {}", ref.chip, ref.line);
    throw_errno(errno, "cannot look up line " + ref.line, ref.chip);
  }
  return l;
}

std::string consumer_of(gpiod_line* line) {
  gpiod_line_update(line);
  const char* c = gpiod_line_consumer(line);
  return c && *c ? c : "the kernel or an unnamed consumer";
}

std::string describe(const GpioLineRef& ref, gpiod_line* line) {
  const char* name = gpiod_line_name(line);
  return fmt::format("{} line {}{}{}{}", ref.chip, gpiod_line_offset(line), name ? " (" : "", name ? name : "", name ? ")" : "");
}

void request_output(gpiod_line* line, const std::string& who, bool active_low, bool initial, const std::string& where) {
  const int flags = active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
  errno = 0;
  if (gpiod_line_request_output_flags(line, "capture", flags, initial ? 1 : 0) < 0) {
    const int err = errno;
    if (err == EBUSY) throw make_error(Status::device_error, "{}: {} is busy, held by '{}'", who, where, consumer_of(line));
    throw_errno(err, who + ": cannot request the line", where);
  }
}

}  // namespace gpio

using namespace gpio;

GpioLineRef parse_gpio_uri(const std::string& uri) {
  if (uri.rfind("gpio:", 0) != 0) throw usage_error("not a gpio: light URI: {}", uri);
  GpioLineRef r;
  bool have_line = false;
  for (const capture::DeviceOption& o : capture::split_device_options(uri.substr(5))) {
    const std::string& key = o.key;
    const std::string& value = o.value;
    const std::string& item = o.item;
    if (key == "chip" && !value.empty()) {
      r.chip = value;
    } else if (key == "line" && !value.empty()) {
      r.line = value;
      have_line = true;
    } else if (key == "active_low" && (!o.has_value || value == "1" || value == "true")) {
      r.active_low = true;
    } else if (key == "active_low" && (value == "0" || value == "false")) {
      r.active_low = false;
    } else {
      throw usage_error("gpio light URI: bad item '{}' in {} (chip=NAME, line=NAME|OFFSET, active_low)", item, uri);
    }
  }
  if (!have_line) throw usage_error("gpio light URI needs line=NAME|OFFSET: {}", uri);
  return r;
}

GpioLightBank::GpioLightBank(const std::vector<GpioLightSpec>& lights) {
  try {
    for (const GpioLightSpec& spec : lights) {
      if (std::any_of(lights_.begin(), lights_.end(), [&](const Light& l) { return l.id == spec.id; }))
        throw usage_error("light '{}' listed twice", spec.id);
      auto chip = std::find_if(chips_.begin(), chips_.end(), [&](const Chip& c) { return c.name == spec.ref.chip; });
      if (chip == chips_.end()) {
        chips_.push_back({spec.ref.chip, open_chip(spec.ref.chip)});
        chip = chips_.end() - 1;
      }
      gpiod_line* line = find_line(chip->chip, spec.ref);
      const std::string where = describe(spec.ref, line);
      for (const Light& l : lights_)
        if (l.line == line) throw usage_error("lights '{}' and '{}' are both on {}", l.id, spec.id, where);
      request_output(line, "light " + spec.id, spec.ref.active_low, spec.initial_on, where);
      lights_.push_back({spec.id, where, line, spec.initial_on});
    }
  } catch (...) {
    // Lines already requested lit must not stay lit because a later one failed.
    for (Light& l : lights_)
      if (l.on) gpiod_line_set_value(l.line, 0);
    release();
    throw;
  }
}

GpioLightBank::~GpioLightBank() {
  if (!keep_) {
    for (Light& l : lights_)
      if (l.line && l.on) gpiod_line_set_value(l.line, 0);  // best effort: nothing to report to
  }
  release();
}

void GpioLightBank::release() noexcept {
  for (Light& l : lights_)
    if (l.line) gpiod_line_release(l.line);
  lights_.clear();
  for (Chip& c : chips_) gpiod_chip_close(c.chip);
  chips_.clear();
}

std::vector<capture::LightState> GpioLightBank::list() {
  std::vector<capture::LightState> out;
  for (const Light& l : lights_) out.push_back({l.id, l.on});
  return out;
}

void GpioLightBank::set(const std::string& id, bool on) {
  auto it = std::find_if(lights_.begin(), lights_.end(), [&](const Light& l) { return l.id == id; });
  if (it == lights_.end()) throw usage_error("no light '{}' in the station", id);
  errno = 0;
  if (gpiod_line_set_value(it->line, on ? 1 : 0) < 0) throw_errno(errno, "light " + id + ": cannot set the line", it->where);
  it->on = on;
}

void GpioLightBank::all_off() {
  for (Light& l : lights_) set(l.id, false);
}

std::string probe_gpio_line(const GpioLineRef& ref) {
  gpiod_chip* chip = open_chip(ref.chip);
  try {
    gpiod_line* line = find_line(chip, ref);
    const std::string state = gpiod_line_is_used(line) ? "used by " + consumer_of(line) : "free";
    gpiod_chip_close(chip);
    return state;
  } catch (...) {
    gpiod_chip_close(chip);
    throw;
  }
}

}  // namespace fest::devices

#include "devices/usb_aux_lights.hpp"

#include <algorithm>
#include <cstdlib>

#include "core/error.hpp"

namespace fest::devices {

UsbAuxRef parse_usb_aux_uri(const std::string& uri) {
  if (uri.rfind("usb-aux:", 0) != 0) throw usage_error("not a usb-aux: light URI: {}", uri);
  UsbAuxRef r;
  std::string rest = uri.substr(8);
  const std::size_t comma = rest.find(',');
  const std::string n = rest.substr(0, comma);
  char* end = nullptr;
  const unsigned long aux = std::strtoul(n.c_str(), &end, 10);
  if (n.empty() || end != n.c_str() + n.size() || aux > 15)
    throw usage_error("usb-aux light URI: '{}' is not an aux output 0..15 (in {})", n, uri);
  r.aux = unsigned(aux);
  if (comma != std::string::npos) {
    const std::string opt = rest.substr(comma + 1);
    if (opt.rfind("usb=", 0) != 0 || opt.find(',') != std::string::npos)
      throw usage_error("usb-aux light URI: expected usb=VID:PID#SERIAL after the output number (in {})", uri);
    r.device_uri = "usb:" + opt.substr(4);
  }
  r.device = parse_usb_uri(r.device_uri);
  return r;
}

UsbAuxLightBank::UsbAuxLightBank(const std::vector<UsbAuxLightSpec>& lights) {
  if (lights.empty()) throw usage_error("no usb-aux lights to open");
  std::uint16_t mask = 0, values = 0;
  // One controller: the same VID:PID, and the same serial where both name one (the
  // more specific selector wins).
  UsbSelector device = lights.front().ref.device;
  for (const UsbAuxLightSpec& l : lights) {
    const UsbSelector& d = l.ref.device;
    if (d.vid != device.vid || d.pid != device.pid || (!d.serial.empty() && !device.serial.empty() && d.serial != device.serial))
      throw usage_error("lights {} and {} are on different controllers ({}, {})", lights.front().id, l.id,
                        lights.front().ref.device_uri, l.ref.device_uri);
    if (device.serial.empty()) device.serial = d.serial;
    for (const Light& o : lights_) {
      if (o.id == l.id) throw usage_error("light '{}' listed twice", l.id);
      if (o.aux == l.ref.aux) throw usage_error("lights '{}' and '{}' are both aux output {}", o.id, l.id, o.aux);
    }
    lights_.push_back({l.id, l.ref.aux, l.initial_on});
    mask = std::uint16_t(mask | (1u << l.ref.aux));
    if (l.initial_on) values = std::uint16_t(values | (1u << l.ref.aux));
  }
  controller_ = std::make_unique<UsbTurntable>(device, false);
  const capture::ttp1::Info& info = controller_->ttp_info();
  for (const Light& l : lights_)
    if (!info.has_aux || l.aux >= info.n_aux)
      throw make_error(Status::device_not_found, "light {}: the controller '{}' has no aux output {} (it has {})", l.id,
                       info.name, l.aux, info.has_aux ? info.n_aux : 0);
  controller_->set_aux(mask, values);
}

UsbAuxLightBank::~UsbAuxLightBank() {
  if (keep_ || !controller_) return;
  std::uint16_t mask = 0;
  for (const Light& l : lights_)
    if (l.on) mask = std::uint16_t(mask | (1u << l.aux));
  if (!mask) return;
  try {
    controller_->set_aux(mask, 0);
  } catch (const Error&) {
    // Best effort: the controller is gone or refuses; nothing to report to here.
  }
}

std::vector<capture::LightState> UsbAuxLightBank::list() {
  std::vector<capture::LightState> out;
  for (const Light& l : lights_) out.push_back({l.id, l.on});
  return out;
}

void UsbAuxLightBank::set(const std::string& id, bool on) {
  auto it = std::find_if(lights_.begin(), lights_.end(), [&](const Light& l) { return l.id == id; });
  if (it == lights_.end()) throw usage_error("no light '{}' in the station", id);
  const std::uint16_t bit = std::uint16_t(1u << it->aux);
  controller_->set_aux(bit, on ? bit : 0);
  it->on = on;
}

void UsbAuxLightBank::all_off() {
  std::uint16_t mask = 0;
  for (const Light& l : lights_) mask = std::uint16_t(mask | (1u << l.aux));
  controller_->set_aux(mask, 0);
  for (Light& l : lights_) l.on = false;
}

}  // namespace fest::devices

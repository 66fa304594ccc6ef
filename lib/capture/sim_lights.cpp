#include "capture/sim_lights.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::capture {

SimLightBank::SimLightBank(std::vector<std::string> ids) {
  for (std::string& id : ids) {
    if (id.empty()) throw usage_error("sim lights: empty light id");
    if (std::any_of(lights_.begin(), lights_.end(), [&](const LightState& l) { return l.id == id; }))
      throw usage_error("sim lights: light '{}' listed twice", id);
    lights_.push_back({std::move(id), false});
  }
}

SimLightBank::~SimLightBank() {
  for (LightState& l : lights_) l.on = false;
}

std::vector<LightState> SimLightBank::list() { return lights_; }

void SimLightBank::set(const std::string& id, bool on) {
  auto it = std::find_if(lights_.begin(), lights_.end(), [&](const LightState& l) { return l.id == id; });
  if (it == lights_.end()) throw usage_error("no light '{}' in the station", id);
  if (it->on == on) return;
  it->on = on;
  timeline_.push_back({id, on});
}

void SimLightBank::all_off() {
  for (const LightState& l : lights_)
    if (l.on) set(l.id, false);
}

}  // namespace fest::capture

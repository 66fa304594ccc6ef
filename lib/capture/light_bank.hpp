#pragma once
// The light bank every backend implements (docs/capture.md §4, docs/lights.md §3): a set of named
// on/off lights. A backend holds its lines while it is alive, because a GPIO value is only
// guaranteed while the line stays requested; destroying it switches every light off.

#include <string>
#include <vector>

namespace fest::capture {

struct LightState {
  std::string id;
  bool on = false;
};

// Backends throw fest::Error with the device exit statuses (README "Conventions"): device_not_found (5),
// device_error (6, e.g. a line busy with another consumer, named in the message),
// permission (8, naming the group or udev rule that is missing).
class LightBank {
 public:
  virtual ~LightBank() = default;
  virtual std::vector<LightState> list() = 0;      // in the station's order
  virtual void set(const std::string& id, bool on) = 0;  // usage_error for an unknown id
  virtual void all_off() = 0;
  // For one-shot commands (`lights on L0`): release the lines as they are set instead
  // of switching everything off. Most GPIO drivers keep an output's level after release,
  // the kernel does not promise it (`lights hold` is the guaranteed way). Simulated
  // banks ignore it.
  virtual void keep_state_on_release() {}
  // Exactly this light on, every other off (the acquisition loop's step, docs/capture.md §2).
  void only(const std::string& id) {
    for (const LightState& l : list())
      if (l.id != id && l.on) set(l.id, false);
    set(id, true);
  }
};

}  // namespace fest::capture

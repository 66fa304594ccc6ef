#pragma once
// In-process light bank for tests and simulated sessions (URI `sim:` for a light,
// docs/capture.md §4.2). It keeps a timeline of every switch so tests can assert
// what was lit when (e.g. exactly the planned light during each exposure, all off after
// an abort); the simulated camera reads list() to know which lights illuminate the scene.

#include <string>
#include <vector>

#include "capture/light_bank.hpp"

namespace fest::capture {

struct LightEvent {
  std::string id;
  bool on = false;
};

class SimLightBank : public LightBank {
 public:
  // usage_error for an empty or duplicated id.
  explicit SimLightBank(std::vector<std::string> ids);
  ~SimLightBank() override;  // switches everything off, as a real bank does on release
  std::vector<LightState> list() override;
  void set(const std::string& id, bool on) override;
  void all_off() override;

  // Only actual changes are recorded (switching a lit light on again is not an event).
  const std::vector<LightEvent>& timeline() const { return timeline_; }

 private:
  std::vector<LightState> lights_;
  std::vector<LightEvent> timeline_;
};

}  // namespace fest::capture

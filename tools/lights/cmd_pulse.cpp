// lights pulse: one light on for --ms milliseconds, then off (docs/lights.md §2).

#include "commands.hpp"
#include "timed_lights.hpp"

namespace fest::lights_tool {

int pulse_command(const StationOptions& s, const PulseOptions& o) { return lit_for(s, {o.id}, double(o.ms) / 1000.0); }

}  // namespace fest::lights_tool

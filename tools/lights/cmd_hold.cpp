// lights hold: lights on until --time passes or a stop signal, then off (docs/lights.md §2).

#include "commands.hpp"
#include "timed_lights.hpp"

namespace fest::lights_tool {

int hold_command(const StationOptions& s, const HoldOptions& o) { return lit_for(s, o.ids, o.seconds > 0 ? o.seconds : -1); }

}  // namespace fest::lights_tool

// turntable stop: decelerate to a stop (--now: at once); prints nothing.

#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int stop_command(const DeviceOptions& d, bool now) {
  const OpenTurntable t(d);
  t->stop(now);
  return 0;
}

}  // namespace fest::turntable_tool

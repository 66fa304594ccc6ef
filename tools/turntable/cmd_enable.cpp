// turntable enable / disable: power or unpower the motor driver (one call); prints nothing.

#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int enable_command(const DeviceOptions& d, bool enable) {
  const OpenTurntable t(d);
  t->enable(enable);
  return 0;
}

}  // namespace fest::turntable_tool

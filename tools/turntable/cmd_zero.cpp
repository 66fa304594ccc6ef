// turntable zero: the current position becomes 0; prints nothing.

#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int zero_command(const DeviceOptions& d) {
  const OpenTurntable t(d);
  t->set_zero();
  return 0;
}

}  // namespace fest::turntable_tool

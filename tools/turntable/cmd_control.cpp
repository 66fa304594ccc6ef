// turntable stop / zero / enable / disable: one device call each, printing nothing.

#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int stop_command(const DeviceOptions& d, bool now) {
  const OpenTurntable t(d);
  t->stop(now);
  return 0;
}

int zero_command(const DeviceOptions& d) {
  const OpenTurntable t(d);
  t->set_zero();
  return 0;
}

int enable_command(const DeviceOptions& d, bool enable) {
  const OpenTurntable t(d);
  t->enable(enable);
  return 0;
}

}  // namespace fest::turntable_tool

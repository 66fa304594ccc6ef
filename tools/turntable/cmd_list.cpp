// turntable list: the TTP/1 devices matching the URI's VID:PID, or the simulator.

#include <fmt/format.h>

#include "commands.hpp"
#include "device.hpp"
#include "devices/open_devices.hpp"
#include "devices/usb_turntable.hpp"

namespace fest::turntable_tool {

int list_command(const DeviceOptions& d) {
  const std::string uri = device_uri(d);
  nlohmann::json j = nlohmann::json::array();
  std::string text;
  if (uri.rfind("usb", 0) == 0) {
    for (const auto& l : devices::list_usb_turntables(devices::parse_usb_uri(uri))) {
      j.push_back({{"uri", l.uri}, {"product", l.product}, {"bus", l.bus}, {"address", l.address}, {"problem", l.problem}});
      text += l.problem.empty() ? fmt::format("{}\t{}\tbus {} device {}\n", l.uri, l.product, l.bus, l.address)
                                : fmt::format("{}\t(unusable: {})\n", l.uri, l.problem);
    }
  } else {
    devices::open_turntable(uri);  // a simulator is always there; just check the URI
    j.push_back({{"uri", uri}, {"product", "fest sim turntable"}});
    text = uri + "\tfest sim turntable\n";
  }
  print(d, j, text);
  return 0;
}

}  // namespace fest::turntable_tool

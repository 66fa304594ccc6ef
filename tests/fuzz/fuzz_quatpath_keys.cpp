// quatpath's key file reader (tools/quatpath/keys_io: read_keys), CSV/TSV or JSON Lines
// by content, then the path through up to 64 keys it accepted (lib/motionpath: its key
// checks, then poses at both ends and between, for every position mode, slerp and
// squad, and constant speed): any bytes must give keys and poses, or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "keys_io.hpp"
#include "motionpath/path.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    int dropped = 0;
    const auto keys = fest::quatpath_tool::read_keys(bytes, "keys", fest::motionpath::Way::shortest, dropped);
    if (keys.size() > 64) return 0;
    for (int mode = 0; mode < 3; ++mode) {
      fest::motionpath::PathOptions opt;
      opt.position = static_cast<fest::motionpath::PositionMode>(mode);  // linear, catmull_rom, kb
      opt.orientation = mode == 2 ? fest::motionpath::OrientationMode::squad : fest::motionpath::OrientationMode::slerp;
      opt.constant_speed = mode == 1;
      try {
        const fest::motionpath::Path path(keys, opt);
        const double a = path.t_begin(), b = path.t_end();
        for (double u : {0.0, 0.37, 1.0}) path.at(a + u * (b - a));
      } catch (const fest::Error&) {
      }
    }
  } catch (const fest::Error&) {
  }
  return 0;
}

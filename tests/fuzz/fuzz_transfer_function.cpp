// volrender's transfer function file (lib/raycast/transfer_function): CSV rows or
// ParaView's colour-map JSON, in both opacity modes, then the tabulation it is rendered
// with. The documented failure is std::invalid_argument naming the line; fest::Error is
// accepted too. Anything else (another exception, a crash) is a finding.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/error.hpp"
#include "raycast/transfer_function.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest::raycast;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (OpacityMode mode : {OpacityMode::opacity, OpacityMode::extinction}) {
    try {
      auto points = parse_transfer_function(text, -3.0, 250.0, mode);
      const TransferFunction tf(std::move(points), -3.0, 250.0, mode, 0.5);
      for (double v : {-10.0, -3.0, 0.0, 100.0, 250.0, 1e9}) {
        tf.at(v);
        tf.integral_tau(v);
      }
    } catch (const std::invalid_argument&) {
    } catch (const fest::Error&) {
    }
  }
  return 0;
}

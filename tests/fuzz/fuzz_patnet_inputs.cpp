// The inputs of `patnet run` from files (tools/patnet/inputs): the JSON Lines events
// (parse_events) and the TSV table (parse_table). Any bytes must give events or a table,
// or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "inputs.hpp"
#include "patnet/machine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    static fest::patnet::Machine m;  // values are made in it; one for all inputs (building one is slow)
    fest::patnet_tool::parse_events(bytes, "events", m);
  } catch (const fest::Error&) {
  }
  try {
    fest::patnet_tool::parse_table(bytes, "table", "sensor");
  } catch (const fest::Error&) {
  }
  return 0;
}

// lmfsim's trajectory CSV (tools/lmfsim/trajectory_csv: parse_trajectory), read by
// `lmfsim diff` and `lmfsim export`. Any bytes must give rows or a clean fest::Error, and
// rows written back with append_row must read back to the same rows.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "trajectory_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest::lmfsim_tool;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::vector<TrajectoryRow> rows;
  try {
    rows = parse_trajectory(bytes, "trajectory.csv");
  } catch (const fest::Error&) {
    return 0;
  }
  std::string again = trajectory_header();
  for (const TrajectoryRow& r : rows) append_row(again, r);
  try {
    if (parse_trajectory(again, "again").size() != rows.size()) __builtin_trap();
  } catch (const fest::Error&) {
    __builtin_trap();  // what fest writes, fest must read
  }
  return 0;
}

// facefit's landmark files (formats/facemodel/landmarks_io): observations (TSV or iBUG
// .pts), landmark-to-vertex maps (TSV or the eos TOML subset) and vertex sets. What reads
// as observations must write and read again to the same count. Any bytes must give
// entries or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/facemodel/landmarks_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest::formats;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto entries = read_landmarks(text, "fuzz", 1.0);
    if (!entries.empty()) {
      try {
        if (read_landmarks(write_landmarks(entries), "round trip", 0.0).size() != entries.size()) __builtin_trap();
      } catch (const fest::Error&) {
        __builtin_trap();  // what was read must write and read back
      }
    }
  } catch (const fest::Error&) {
  }
  try {
    read_landmark_map(text, "fuzz");
  } catch (const fest::Error&) {
  }
  try {
    read_vertex_set(text, "fuzz");
  } catch (const fest::Error&) {
  }
  return 0;
}

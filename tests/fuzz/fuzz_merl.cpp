// The MERL .binary BRDF table reader (formats/brdf/merl_io, what `brdffit fit --merl`
// reads): any bytes either decode or throw fest::Error. A whole table is 35 MB, beyond
// libFuzzer's input sizes, so this exercises the header and size checks that guard it.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/brdf/merl_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    fest::formats::read_merl(bytes);
  } catch (const fest::Error&) {
  }
  return 0;
}

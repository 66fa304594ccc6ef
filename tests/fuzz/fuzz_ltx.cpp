// The .ltx lumitexel decoder (lib/brdffit/ltx_format, docs/brdffit.md §4): any bytes
// either decode or throw fest::Error; nothing reads outside the input, and the record
// counts of a header never allocate beyond what the bytes can hold.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdffit/ltx_format.hpp"
#include "core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<std::uint8_t> bytes(data, data + size);
  nlohmann::json header;
  try {
    fest::brdffit::decode_ltx(bytes, &header);
  } catch (const fest::Error&) {
  }
  return 0;
}

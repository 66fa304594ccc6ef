// The .ltw weights decoder (lib/brdffit/ltw_format, docs/brdffit.md §5): any bytes either
// decode or throw fest::Error; nothing reads outside the input.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "brdffit/ltw_format.hpp"
#include "core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  nlohmann::json header;
  try {
    fest::brdffit::decode_ltw(bytes, &header);
  } catch (const fest::Error&) {
  }
  return 0;
}

// The .tlp archive head, index and nodata section decoder (lib/terrainlod/tlp_archive): any bytes either
// decode or throw fest::Error; nothing reads outside the input.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "terrainlod/tlp_archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fest::terrainlod;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const TlpHead head = decode_tlp_head(bytes);
    decode_tlp_index(bytes, head.index_at);
    decode_tlp_nodata(bytes, head);
  } catch (const fest::Error&) {
  }
  return 0;
}

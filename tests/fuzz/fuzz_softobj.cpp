// softobj's decoders: the skeleton scene JSON, the phoneme table, the timeline and the
// palate (decode_palate).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "softobj/coarticulation.hpp"
#include "softobj/palate.hpp"
#include "softobj/skeleton_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)fest::softobj::decode_skeleton(text);
  } catch (const fest::Error&) {
  }
  try {
    (void)fest::softobj::decode_phoneme_table(text);
  } catch (const fest::Error&) {
  }
  try {
    fest::softobj::PhonemeTable t;
    t.phonemes["a"] = {};
    t.phonemes["b"] = {};
    (void)fest::softobj::decode_timeline(text, t);
  } catch (const fest::Error&) {
  }
  try {
    (void)fest::softobj::decode_palate(text);
  } catch (const fest::Error&) {
  }
  return 0;
}

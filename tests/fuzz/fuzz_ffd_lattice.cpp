// libFuzzer target: raw bytes into ffd's own decoders -- lattice JSON, PyGeM .prm and the
// joints table -- then, for a decoded lattice, encoding it again and deforming a point
// (a decoded lattice must be valid: no crash, no NaN from a degenerate box).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "ffd/lattice_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (int which = 0; which < 2; ++which) {
    try {
      const fest::ffd::Lattice l = which == 0 ? fest::ffd::decode_lattice_json(bytes) : fest::ffd::decode_pygem_prm(bytes);
      (void)fest::ffd::decode_lattice_json(fest::ffd::encode_lattice_json(l));
      const fest::ffd::Deformer d(l);
      (void)d.apply(l.origin + 0.5 * (l.axes[0] + l.axes[1] + l.axes[2]));
    } catch (const fest::Error&) {
    }
  }
  try {
    (void)fest::ffd::decode_joints(bytes);
  } catch (const fest::Error&) {
  }
  return 0;
}

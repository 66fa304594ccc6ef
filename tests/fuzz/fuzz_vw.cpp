// Feeds bytes to the .vw decoder (volwave). The hashes would stop almost every mutation
// at the door, so the target reseals the header and chunk hashes first and the fuzzer
// explores the header parser, the chunk tables, the subband slabs of every kind
// (adaptive range-coded slabs, static slabs with their rANS table descriptions and
// streams, and -- format versions 4 and 5 -- packed slabs: width tokens and packed
// bits, with tables of 2^5..2^11 entries in version 5) and the outlier list behind them;
// start the corpus from real .vw files (volwave encode output, e.g. tests/data/volwave/:
// smooth_e0.5.vw and sparse_e1e-3_v5.vw are version 5 with packed slabs at lower table
// precisions, smooth_e0.5_v4.vw version 4, the others version 3; smooth_lossless.vw and
// sparse_lossless.vw hold static slabs). A
// clean fest::Error is the only allowed failure; a file that decodes must decode again
// to the same voxels, and truncations of it must decode or fail cleanly too.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "wavelet/vw_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fest::wavelet;
  constexpr std::uint64_t kMaxFuzzVoxels = 1 << 18;  // keeps every allocation small
  std::string bytes(reinterpret_cast<const char*>(data), size);
  reseal_vw(bytes, kMaxFuzzVoxels);
  try {
    const DecodeResult a = decode_vw(bytes, 1, -1, kMaxFuzzVoxels);
    const DecodeResult b = decode_vw(bytes, 2, -1, kMaxFuzzVoxels);
    if (a.volume.voxels.size() != b.volume.voxels.size()) std::abort();
    if (std::memcmp(a.volume.voxels.data(), b.volume.voxels.data(), a.volume.voxels.size() * sizeof(double)) != 0) std::abort();
    (void)decode_vw(std::string_view(bytes).substr(0, size / 2), 1, -1, kMaxFuzzVoxels);
  } catch (const fest::Error&) {
  }
  return 0;
}

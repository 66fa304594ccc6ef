// Feeds bytes to the .ebm decoder. The CRC would stop almost every mutation at the door,
// so the target reseals the stream (recomputes its CRC) first and the fuzzer explores the
// header, the section parser and the range-coded sections behind it; the corpus should
// start from real .ebm files (ebcode output; tests/data/ebm holds 1.0 streams, their
// 2.0 twins, and 2.1 streams whose GEOM section is version 3: rANS tables, a rANS stream
// and raw bits, residual_tokens.hpp). A clean fest::Error is the only allowed failure; a stream that decodes must
// decode again to the same mesh (determinism), and its header must report the counts of
// that mesh (2.0 does not store them: read_ebm_header decodes; 1.0 checks them).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "edgebreaker/ebm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fest::edgebreaker;
  std::string bytes(reinterpret_cast<const char*>(data), size);
  reseal_ebm(bytes);
  try {
    const MeshSoup a = decode_ebm(bytes);
    const MeshSoup b = decode_ebm(bytes);
    if (a.triangles != b.triangles || a.positions.size() != b.positions.size()) std::abort();
    for (const Triangle& t : a.triangles)
      for (int v : t)
        if (v < 0 || static_cast<std::size_t>(v) >= a.positions.size()) std::abort();
    const EbmHeader h = read_ebm_header(bytes);
    if (h.vertices != a.positions.size() || h.faces != a.triangles.size()) std::abort();
  } catch (const fest::Error&) {
  }
  return 0;
}

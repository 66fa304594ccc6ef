// Feeds raw bytes to the Edgebreaker decoder: each byte's value mod 5 is one CLERS
// symbol, so every input is a symbol string and the fuzzer explores the decoder's
// state space rather than the parser's. A clean fest::Error is the only allowed failure;
// an accepted string must decode to a mesh that encodes back to the same string.
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstdlib>

#include "core/error.hpp"
#include "edgebreaker/clers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fest::edgebreaker;
  Clers clers;
  clers.reserve(size);
  for (size_t i = 0; i < size; ++i) clers.push_back(static_cast<Symbol>(data[i] % 5));
  try {
    const std::vector<Triangle> triangles = decode(clers);
    const Encoded again = encode(triangles, static_cast<int>(std::count(clers.begin(), clers.end(), Symbol::C)) + 3);
    if (again.clers != clers) std::abort();  // decode must be the exact inverse of encode
  } catch (const fest::Error&) {
  }
  return 0;
}

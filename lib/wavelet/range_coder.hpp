#pragma once
// The entropy coders of a .vw subband slab (docs/volwave.md §4): lib/core's adaptive
// binary range coder (core/range_coder.hpp) with a BitModel per context, ended with as
// few bytes as identify the final interval, and a plain bit stream for the bits that no
// model predicts (the low bits of large magnitudes). A slab has two range-coded streams
// and one bit stream: their decoding chains are independent, so a CPU overlaps them.

#include <cstdint>
#include <string>
#include <string_view>

#include "core/bit_stream.hpp"
#include "core/range_coder.hpp"

namespace fest::wavelet {

// Probability of a 0 bit in units of 1/2048, adapted after every coded bit.
struct BitModel {
  std::uint16_t p = range_coding::probability_half;
};

class RangeEncoder {
 public:
  __attribute__((always_inline)) void encode(BitModel& m, int bit) { coder_.bit(m.p, bit); }
  // Ends the stream (range_coding::RangeEncoder::finish: the shortest tail) and returns it.
  std::string finish() { return coder_.finish(); }

 private:
  range_coding::RangeEncoder coder_;
};

// Reads what RangeEncoder wrote. Reading past the end yields zero bytes, so a truncated
// or corrupt stream can never read outside `bytes`; truncated() says that more zeros
// were needed than the shortest tail leaves out, which the caller turns into an error.
class RangeDecoder {
 public:
  explicit RangeDecoder(std::string_view bytes) : coder_(bytes, range_coding::RangeDecoder::FirstByte::implied) {}
  __attribute__((always_inline)) int decode(BitModel& m) { return coder_.bit(m.p); }
  bool truncated() const noexcept { return coder_.truncated(); }

 private:
  range_coding::RangeDecoder coder_;
};

// The plain bit stream (BitWriter, BitReader) is lib/core's, shared with the static rANS
// tables (core/bit_stream.hpp).
using range_coding::BitReader;
using range_coding::BitWriter;

}  // namespace fest::wavelet

#pragma once
// The adaptive binary range coder that turns the context models of band_coder.hpp into
// bytes (docs/volwave.md §4): lib/core's coder (core/range_coder.hpp) in the .vw stream's
// form, a BitModel per context and LZMA's five flush bytes at the end. It has no model of
// its own.

#include <cstdint>
#include <string>
#include <string_view>

#include "core/range_coder.hpp"

namespace fest::wavelet {

// Probability of a 0 bit in units of 1/2048, adapted after every coded bit.
struct BitModel {
  std::uint16_t p = range_coding::probability_half;
};

class RangeEncoder {
 public:
  __attribute__((always_inline)) void encode(BitModel& m, int bit) { coder_.bit(m.p, bit); }
  // A bit of probability 1/2 with no model (low bits of large magnitudes).
  void encode_direct(int bit) { coder_.bypass(bit); }
  // Flushes and returns the coded bytes.
  std::string finish() { return coder_.finish_flushed(); }

 private:
  range_coding::RangeEncoder coder_;
};

// Reads what RangeEncoder wrote. Reading past the end yields zero bytes and sets
// overrun(), so a truncated or corrupt stream can never read outside `bytes`; the
// caller turns overrun() into an error.
class RangeDecoder {
 public:
  explicit RangeDecoder(std::string_view bytes) : coder_(bytes, range_coding::RangeDecoder::FirstByte::stored) {}
  __attribute__((always_inline)) int decode(BitModel& m) { return coder_.bit(m.p); }
  __attribute__((always_inline)) int decode_direct() { return coder_.bypass(); }
  bool overrun() const noexcept { return coder_.overrun() != 0; }

 private:
  range_coding::RangeDecoder coder_;
};

}  // namespace fest::wavelet

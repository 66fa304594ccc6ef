#pragma once
// LSB-first bit packing for the tile body (docs/terrainlod.md §4) and zig-zag mapping of
// signed deltas.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace fest::terrainlod {

inline std::uint64_t zigzag(std::int64_t v) { return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63); }
inline std::int64_t unzigzag(std::uint64_t u) { return static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1); }

// Bits needed for an unsigned value (0 for 0).
inline int bit_width(std::uint64_t v) {
  int b = 0;
  while (b < 64 && (v >> b) != 0) ++b;
  return b;
}

// Rice codes (Golomb with a power-of-two divisor 2^k): the quotient in unary, then k low
// bits; quotients of kRiceEscape or more send the value's width and all its bits. Suited to
// the geometric-looking distributions of prediction residuals.
constexpr int kRiceEscape = 24;

// Bits of `values` Rice coded with parameter k.
inline std::uint64_t rice_bits(const std::vector<std::uint64_t>& values, int k) {
  std::uint64_t bits = 0;
  for (std::uint64_t v : values) {
    const std::uint64_t q = v >> k;
    bits += q >= kRiceEscape ? kRiceEscape + 7 + 64 : q + 1 + static_cast<std::uint64_t>(k);
  }
  return bits;
}

// The k in 0..40 that codes `values` in the fewest bits (the first of equals). Beyond the
// widest value's width every quotient is 0 and the cost only grows with k, so the search
// stops there.
inline int best_rice_k(const std::vector<std::uint64_t>& values) {
  std::uint64_t widest = 0;
  for (std::uint64_t v : values) widest |= v;
  const int last = std::min(40, bit_width(widest));
  int best_k = 0;
  std::uint64_t best = ~std::uint64_t{0};
  for (int k = 0; k <= last; ++k) {
    const std::uint64_t bits = rice_bits(values, k);
    if (bits < best) best = bits, best_k = k;
  }
  return best_k;
}

// Bits are gathered in a 64-bit accumulator and leave it a byte at a time (a bit-by-bit
// writer and reader were most of the tile coding's time).
class BitWriter {
 public:
  void put_rice(std::uint64_t value, int k) {
    const std::uint64_t q = value >> k;
    if (q >= kRiceEscape) {
      put((std::uint64_t{1} << kRiceEscape) - 1, kRiceEscape);
      const int w = bit_width(value);
      put(static_cast<std::uint64_t>(w), 7);
      put(value, w);
      return;
    }
    put((std::uint64_t{1} << q) - 1, static_cast<int>(q));
    put(0, 1);
    put(value, k);
  }
  // The low `bits` bits of value (the rest is ignored), least significant first.
  void put(std::uint64_t value, int bits) {
    if (bits <= 0) return;
    if (bits > 56) {  // keep pending (< 8) + bits within the accumulator
      put(value, 32);
      put(value >> 32, bits - 32);
      return;
    }
    acc_ |= (value & ((std::uint64_t{1} << bits) - 1)) << pending_;
    pending_ += bits;
    for (; pending_ >= 8; pending_ -= 8, acc_ >>= 8) bytes_.push_back(static_cast<char>(acc_ & 0xff));
  }
  // The bytes written, the last one padded with zero bits.
  std::string take() {
    if (pending_ > 0) bytes_.push_back(static_cast<char>(acc_ & 0xff));
    acc_ = 0;
    pending_ = 0;
    return std::move(bytes_);
  }

 private:
  std::string bytes_;
  std::uint64_t acc_ = 0;  // bits not yet in bytes_, first in the low end
  int pending_ = 0;        // how many (< 8 between calls)
};

class BitReader {
 public:
  BitReader(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}
  std::uint64_t get_rice(int k) {
    // The unary quotient: count the ones before the first zero (at most kRiceEscape, which
    // has no terminating zero).
    const std::size_t left = bits_left();
    const int span = static_cast<int>(std::min<std::size_t>(left, kRiceEscape));
    const std::uint64_t w = peek(span);
    // Trailing ones of w, at most span (w has no bits above span).
    const int q = ~w == 0 ? 64 : std::min(span, __builtin_ctzll(~w));
    if (q == kRiceEscape) {
      pos_ += kRiceEscape;
      const int width = static_cast<int>(get(7));
      if (width > 64) throw bad_input("{}: bad escape width", what_);
      return get(width);
    }
    if (q == span) throw bad_input("{}: section ends early", what_);
    pos_ += static_cast<std::size_t>(q) + 1;
    return (static_cast<std::uint64_t>(q) << k) | get(k);
  }
  std::uint64_t get(int bits) {
    if (bits <= 0) return 0;
    if (bits > 56) {
      const std::uint64_t lo = get(32);
      return lo | (get(bits - 32) << 32);
    }
    if (static_cast<std::size_t>(bits) > bits_left()) throw bad_input("{}: section ends early", what_);
    const std::uint64_t v = peek(bits);
    pos_ += static_cast<std::size_t>(bits);
    return v;
  }

 private:
  std::size_t bits_left() const { return bytes_.size() * 8 - pos_; }
  // The next `bits` (<= 56, <= bits_left()) bits without consuming them.
  std::uint64_t peek(int bits) const {
    if (bits <= 0) return 0;
    const std::size_t first = pos_ >> 3;
    std::uint64_t w = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if (first + 8 <= bytes_.size()) {
      std::memcpy(&w, bytes_.data() + first, 8);
    } else
#endif
    {
      const std::size_t last = std::min(bytes_.size(), first + 8);
      for (std::size_t i = first; i < last; ++i) w |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[i])) << (8 * (i - first));
    }
    return (w >> (pos_ & 7)) & ((std::uint64_t{1} << bits) - 1);
  }

  std::string_view bytes_;
  const char* what_;
  std::size_t pos_ = 0;
};

}  // namespace fest::terrainlod

#pragma once
// LSB-first bit packing for the tile body (spec terrainlod 2.9) and zig-zag mapping of
// signed deltas.

#include <algorithm>
#include <cstdint>
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
    put(value & ((std::uint64_t{1} << k) - 1), k);
  }
  void put(std::uint64_t value, int bits) {
    for (int b = 0; b < bits; ++b) {
      if (used_ == 0) bytes_.push_back('\0');
      if ((value >> b) & 1) bytes_.back() = static_cast<char>(static_cast<unsigned char>(bytes_.back()) | (1u << used_));
      used_ = (used_ + 1) & 7;
    }
  }
  std::string take() {
    used_ = 0;
    return std::move(bytes_);
  }

 private:
  std::string bytes_;
  int used_ = 0;
};

class BitReader {
 public:
  BitReader(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}
  std::uint64_t get_rice(int k) {
    std::uint64_t q = 0;
    while (q < kRiceEscape && get(1)) ++q;
    if (q == kRiceEscape) {
      const int w = static_cast<int>(get(7));
      if (w > 64) throw bad_input("{}: bad escape width", what_);
      return get(w);
    }
    return (q << k) | get(k);
  }
  std::uint64_t get(int bits) {
    std::uint64_t v = 0;
    for (int b = 0; b < bits; ++b, ++pos_) {
      if (pos_ >= bytes_.size() * 8) throw bad_input("{}: section ends early", what_);
      if ((static_cast<unsigned char>(bytes_[pos_ >> 3]) >> (pos_ & 7)) & 1) v |= std::uint64_t{1} << b;
    }
    return v;
  }

 private:
  std::string_view bytes_;
  const char* what_;
  std::size_t pos_ = 0;
};

}  // namespace fest::terrainlod

#pragma once
// LSB-first bit packing for the tile body (spec terrainlod 2.9) and zig-zag mapping of
// signed deltas.

#include <cstdint>
#include <string>
#include <string_view>

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

class BitWriter {
 public:
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

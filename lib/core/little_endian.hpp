#pragma once
// Little-endian integers, IEEE floats and LEB128 varints in byte strings: how fest's own
// containers (.ebm of lib/edgebreaker, .vw of lib/wavelet) store their headers and
// tables. Writing appends to a std::string; reading checks every length against the bytes
// left, and what running out means is the container's to say (Errors below), so each
// keeps its own messages.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace fest::little_endian {

inline void put_u8(std::string& out, std::uint8_t v) { out.push_back(static_cast<char>(v)); }
inline void put_u16(std::string& out, std::uint16_t v) {
  for (int k = 0; k < 2; ++k) put_u8(out, static_cast<std::uint8_t>(v >> (8 * k)));
}
inline void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) put_u8(out, static_cast<std::uint8_t>(v >> (8 * k)));
}
inline void put_u64(std::string& out, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) put_u8(out, static_cast<std::uint8_t>(v >> (8 * k)));
}
inline void put_f32(std::string& out, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_u32(out, bits);
}
inline void put_f64(std::string& out, double f) {
  std::uint64_t bits;
  std::memcpy(&bits, &f, 8);
  put_u64(out, bits);
}
// LEB128: seven bits a byte, low first, the high bit set on all but the last.
inline void put_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    put_u8(out, static_cast<std::uint8_t>((v & 0x7F) | 0x80));
    v >>= 7;
  }
  put_u8(out, static_cast<std::uint8_t>(v));
}

// Any integer type, for containers that check their lengths once up front and then read
// at known offsets (terrainlod's .tlp index and nodata section). `at + sizeof(T)` must lie
// within `bytes`: get_le does not check.
template <class T>
inline void put_le(std::string& out, T v) {
  for (std::size_t b = 0; b < sizeof(T); ++b) out.push_back(static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * b)) & 0xff));
}
template <class T>
inline T get_le(std::string_view bytes, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < sizeof(T); ++b) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + b])) << (8 * b);
  return static_cast<T>(v);
}

// Reads what the put_ functions write, from `pos` on. Errors has
//   [[noreturn]] void truncated(std::size_t needed, std::size_t pos) const;
//   [[noreturn]] void varint_too_long(std::size_t pos) const;
// called when fewer than `needed` bytes are left at `pos`, and for a varint of more
// than 64 bits.
template <class Errors>
class Reader {
 public:
  Reader(std::string_view bytes, Errors errors, std::size_t pos = 0) : bytes_(bytes), errors_(errors), pos_(pos) {}

  std::size_t pos() const { return pos_; }
  std::size_t left() const { return bytes_.size() - pos_; }
  bool done() const { return pos_ == bytes_.size(); }

  std::uint8_t u8() {
    need(1);
    return static_cast<std::uint8_t>(bytes_[pos_++]);
  }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsigned_of(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_of(4)); }
  std::uint64_t u64() { return unsigned_of(8); }
  float f32() {
    const std::uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  double f64() {
    const std::uint64_t bits = u64();
    double f;
    std::memcpy(&f, &bits, 8);
    return f;
  }
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const std::uint8_t b = u8();
      v |= static_cast<std::uint64_t>(b & 0x7F) << shift;
      if (!(b & 0x80)) return v;
    }
    errors_.varint_too_long(pos_);
  }
  std::string_view bytes(std::size_t n) {
    need(n);
    const std::string_view out = bytes_.substr(pos_, n);
    pos_ += n;
    return out;
  }

 private:
  void need(std::size_t n) const {
    if (left() < n) errors_.truncated(n, pos_);
  }
  std::uint64_t unsigned_of(int size) {
    need(static_cast<std::size_t>(size));
    std::uint64_t v = 0;
    for (int k = 0; k < size; ++k) v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(bytes_[pos_ + k])) << (8 * k);
    pos_ += static_cast<std::size_t>(size);
    return v;
  }

  std::string_view bytes_;
  Errors errors_;
  std::size_t pos_;
};

}  // namespace fest::little_endian

#pragma once
// A plain bit stream for bits that no model predicts (the low bits of large magnitudes):
// written low first into bytes. Used by lib/wavelet's slabs (docs/volwave.md §4) and by the
// static rANS table descriptions (core/rans.hpp).

#include <cstdint>
#include <string>
#include <string_view>

namespace fest::range_coding {

// Bits written low first into bytes (the first bit is bit 0 of byte 0).
class BitWriter {
 public:
  // The `count` (0..32) low bits of `value`.
  void put(std::uint64_t value, int count) {
    acc_ |= (value & ((std::uint64_t{1} << count) - 1)) << filled_;
    filled_ += count;
    while (filled_ >= 8) {
      out_.push_back(static_cast<char>(acc_ & 0xFF));
      acc_ >>= 8;
      filled_ -= 8;
    }
  }
  std::string finish() {
    if (filled_ > 0) out_.push_back(static_cast<char>(acc_ & 0xFF));
    acc_ = 0;
    filled_ = 0;
    return std::move(out_);
  }

 private:
  std::string out_;
  std::uint64_t acc_ = 0;
  int filled_ = 0;
};

// Reads what BitWriter wrote; past the end it reads zeros and overrun() turns true.
class BitReader {
 public:
  explicit BitReader(std::string_view bytes)
      : p_(reinterpret_cast<const std::uint8_t*>(bytes.data())), end_(p_ + bytes.size()),
        available_(8 * static_cast<std::uint64_t>(bytes.size())) {}
  // `count` (0..32) bits, the first read in bit 0.
  __attribute__((always_inline)) std::uint64_t get(int count) {
    if (filled_ < count) refill();
    const std::uint64_t v = acc_ & ((std::uint64_t{1} << count) - 1);
    acc_ >>= count;
    filled_ -= count;
    consumed_ += static_cast<std::uint64_t>(count);
    return v;
  }
  // The next `count` (0..32) bits without reading them (get(count) returns the same).
  __attribute__((always_inline)) std::uint64_t peek(int count) {
    if (filled_ < count) refill();
    return acc_ & ((std::uint64_t{1} << count) - 1);
  }
  // More bits were read than the stream holds.
  bool overrun() const noexcept { return consumed_ > available_; }
  // Bits read so far (where a stream that continues after, say, its tables goes on).
  std::uint64_t consumed() const noexcept { return consumed_; }

 private:
  void refill() {
    while (filled_ <= 56) {
      const std::uint64_t byte = p_ < end_ ? *p_++ : 0;
      acc_ |= byte << filled_;
      filled_ += 8;
    }
  }
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  std::uint64_t acc_ = 0;
  int filled_ = 0;
  std::uint64_t available_, consumed_ = 0;
};

}  // namespace fest::range_coding

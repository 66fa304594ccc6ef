#pragma once
// An adaptive binary range coder (the LZMA coder's design: 11-bit probabilities adapted
// by a shift of 5, 32-bit range with carry propagation through a byte cache). It turns
// the context models of band_coder.hpp into bytes; it has no model of its own.

#include <cstdint>
#include <string>
#include <string_view>

namespace fest::wavelet {

// Probability of a 0 bit in units of 1/2048, adapted after every coded bit.
struct BitModel {
  std::uint16_t p = 1024;
};

class RangeEncoder {
 public:
  __attribute__((always_inline)) void encode(BitModel& m, int bit) {
    const std::uint32_t bound = (range_ >> 11) * m.p;
    if (bit == 0) {
      range_ = bound;
      m.p = static_cast<std::uint16_t>(m.p + ((2048 - m.p) >> 5));
    } else {
      low_ += bound;
      range_ -= bound;
      m.p = static_cast<std::uint16_t>(m.p - (m.p >> 5));
    }
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      shift_low();
    }
  }
  // A bit of probability 1/2 with no model (low bits of large magnitudes).
  void encode_direct(int bit) {
    range_ >>= 1;
    if (bit) low_ += range_;
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      shift_low();
    }
  }
  // Flushes and returns the coded bytes.
  std::string finish() {
    for (int i = 0; i < 5; ++i) shift_low();
    return std::move(out_);
  }

 private:
  void shift_low() {
    if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
      const auto carry = static_cast<std::uint8_t>(low_ >> 32);
      std::uint8_t temp = cache_;
      do {
        out_.push_back(static_cast<char>(static_cast<std::uint8_t>(temp + carry)));
        temp = 0xFF;
      } while (--cache_size_ != 0);
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    }
    ++cache_size_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }

  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cache_size_ = 1;
  std::string out_;
};

// Reads what RangeEncoder wrote. Reading past the end yields zero bytes and sets
// overrun(), so a truncated or corrupt stream can never read outside `bytes`; the
// caller turns overrun() into an error.
class RangeDecoder {
 public:
  explicit RangeDecoder(std::string_view bytes) : data_(bytes) {
    for (int i = 0; i < 5; ++i) code_ = (code_ << 8) | next();
  }
  // Branch-free (conditional moves): whether a bit is 0 or 1 is what the coder cannot
  // predict, so a branch on it is mispredicted as often as the data is surprising.
  __attribute__((always_inline)) int decode(BitModel& m) {
    const std::uint32_t p = m.p;
    const std::uint32_t bound = (range_ >> 11) * p;
    const int bit = code_ >= bound;
    const std::uint32_t one = 0u - static_cast<std::uint32_t>(bit);  // all ones for a 1 bit
    code_ -= bound & one;
    range_ = bit ? range_ - bound : bound;
    m.p = static_cast<std::uint16_t>(bit ? p - (p >> 5) : p + ((2048 - p) >> 5));
    normalise();
    return bit;
  }
  __attribute__((always_inline)) int decode_direct() {
    range_ >>= 1;
    const int bit = code_ >= range_;
    code_ -= range_ & (0u - static_cast<std::uint32_t>(bit));
    normalise();
    return bit;
  }
  bool overrun() const noexcept { return overrun_; }

 private:
  __attribute__((always_inline)) void normalise() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      code_ = (code_ << 8) | next();
    }
  }
  std::uint32_t next() {
    if (pos_ < data_.size()) return static_cast<std::uint8_t>(data_[pos_++]);
    overrun_ = true;
    return 0;
  }

  std::string_view data_;
  std::size_t pos_ = 0;
  std::uint32_t code_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  bool overrun_ = false;
};

}  // namespace fest::wavelet

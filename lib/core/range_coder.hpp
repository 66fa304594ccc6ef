#pragma once
// The byte-oriented range coder both of fest's entropy coders use: the .ebm sections of
// lib/edgebreaker (docs/ebcode.md) and the wavelet bands of lib/wavelet (docs/volwave.md).
// LZMA-style: 32-bit range, carry propagated through a cached byte and a count of pending
// 0xFF bytes (arithmetic coding after Witten, Neal & Cleary 1987). Multi-symbol
// frequencies (total <= 2^16), adaptive binary decisions (11-bit probabilities of a 0,
// adapted by a shift, 5 by default) and bypass bits of probability 1/2. Header-only:
// these are the inner loops of both coders.
//
// Two ways to end a stream: finish() writes as few bytes as identify the final interval
// and leaves out the first byte (always 0); finish_flushed() writes LZMA's five flush
// bytes, the first included. The decoder is told which (FirstByte).
//
// The decoder never reads outside its bytes: past the end it reads zeros and counts them,
// and overrun() tells the caller that the stream was cut short.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fest::range_coding {

constexpr std::uint32_t range_top = 1u << 24;
constexpr int probability_bits = 11;
constexpr std::uint16_t probability_half = 1u << (probability_bits - 1);
constexpr int adapt_shift = 5;

class RangeEncoder {
 public:
  void encode(std::uint32_t cum, std::uint32_t freq, std::uint32_t total) {
    const std::uint32_t r = range_ / total;
    low_ += static_cast<std::uint64_t>(r) * cum;
    range_ = r * freq;
    normalise();
  }
  void bit(std::uint16_t& p, int b) { bit_at_rate(p, b, adapt_shift); }
  // The same decision with the adaptation shift given (1..5; ebm v2's counted contexts).
  // Probabilities stay in [31, 2017] (shift 5 cannot leave that range, smaller shifts are
  // only used for a context's first few decisions), so both sub-ranges keep at least
  // 31/2048 of a range >= 2^24, and one byte of renormalisation is always enough.
  void bit_at_rate(std::uint16_t& p, int b, int shift) {
    const std::uint32_t bound = (range_ >> probability_bits) * p;
    if (b == 0) {
      range_ = bound;
      p = static_cast<std::uint16_t>(p + (((1u << probability_bits) - p) >> shift));
    } else {
      low_ += bound;
      range_ -= bound;
      p = static_cast<std::uint16_t>(p - (p >> shift));
    }
    if (range_ < range_top) {
      range_ <<= 8;
      shift_low();
    }
  }
  void bypass(int b) {
    range_ >>= 1;
    if (b) low_ += range_;
    normalise();
  }
  // `count` (1..16) low bits of `value` at once, as one uniform decision over 2^count
  // values (the decoder must read them with the same count).
  void bypass_bits(std::uint32_t value, int count) {
    range_ >>= count;
    low_ += static_cast<std::uint64_t>(value & ((1u << count) - 1u)) * range_;
    normalise();
  }
  // Ends the stream with as few bytes as identify a value in [low, low + range): the
  // decoder reads missing trailing bytes as zeros. The first byte LZMA-style coders write
  // is always 0 (no carry can reach it) and is left out too; the decoder implies it.
  std::string finish() {
    int bytes = 4;
    for (int k = 1; k <= 4; ++k) {
      const int s = 32 - 8 * k;
      const std::uint64_t unit = std::uint64_t{1} << s;
      const std::uint64_t v = (low_ + unit - 1) & ~(unit - 1);
      if (v < low_ + range_) {
        low_ = v;
        bytes = k;
        break;
      }
    }
    for (int i = 0; i <= bytes; ++i) shift_low();
    out_.erase(0, 1);
    return std::move(out_);
  }
  // Ends the stream as LZMA does: all of low flushed, the first (zero) byte kept.
  std::string finish_flushed() {
    for (int i = 0; i < 5; ++i) shift_low();
    return std::move(out_);
  }

 private:
  void normalise() {
    while (range_ < range_top) {
      range_ <<= 8;
      shift_low();
    }
  }
  void shift_low() {
    if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
      const auto carry = static_cast<std::uint8_t>(low_ >> 32);
      std::uint8_t byte = cache_;
      do {
        out_.push_back(static_cast<char>(static_cast<std::uint8_t>(byte + carry)));
        byte = 0xFF;
      } while (--pending_ != 0);
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    }
    ++pending_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }

  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t pending_ = 1;
  std::string out_;
};

class RangeDecoder {
 public:
  // Whether the stream holds the encoder's first byte (finish_flushed) or leaves it out
  // (finish).
  enum class FirstByte { implied, stored };

  explicit RangeDecoder(std::string_view bytes, FirstByte first = FirstByte::implied)
      : next_(reinterpret_cast<const unsigned char*>(bytes.data())), end_(next_ + bytes.size()) {
    if (first == FirstByte::stored) next_byte();  // always 0: shifted out of the code register
    for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
  }
  // The cumulative count the next symbol falls in; call consume() with its interval.
  std::uint32_t target(std::uint32_t total) {
    r_ = range_ / total;
    const std::uint32_t v = code_ / r_;
    return v < total ? v : total - 1;
  }
  void consume(std::uint32_t cum, std::uint32_t freq) {
    code_ -= r_ * cum;
    range_ = r_ * freq;
    normalise();
  }
  int bit(std::uint16_t& p) { return bit_at_rate(p, adapt_shift); }
  // Branch-free: the outcome selects range, code and probability by conditional moves
  // (whether a bit is 0 or 1 is what the coder cannot predict, so a branch on it is
  // mispredicted as often as the data is surprising); one byte of renormalisation
  // suffices (see RangeEncoder::bit_at_rate).
  // Branch-free: the outcome selects range, code and probability by conditional moves
  // (whether a bit is 0 or 1 is what the coder cannot predict, so a branch on it is
  // mispredicted as often as the data is surprising); one byte of renormalisation
  // suffices (see RangeEncoder::bit_at_rate). A caller that branches on the result gets
  // the selects fused into that branch, which costs nothing more.
  int bit_at_rate(std::uint16_t& p, int shift) {
    const std::uint32_t bound = (range_ >> probability_bits) * p;
    const bool one = code_ >= bound;
    const std::uint32_t up = p + (((1u << probability_bits) - p) >> shift), down = p - (p >> shift);
    code_ = one ? code_ - bound : code_;
    range_ = one ? range_ - bound : bound;
    p = static_cast<std::uint16_t>(one ? down : up);
    if (range_ < range_top) {
      range_ <<= 8;
      code_ = (code_ << 8) | next_byte();
    }
    return one ? 1 : 0;
  }
  // The same decision for a caller that only stores the bit: written with a mask, since
  // GCC turns the selects above into a branch on the outcome even then (for nearly uniform
  // bits, such as those below a residual's leading one, mispredicted half the time).
  int bit_value_at_rate(std::uint16_t& p, int shift) {
    const std::uint32_t bound = (range_ >> probability_bits) * p;
    const std::uint32_t one = 0u - static_cast<std::uint32_t>(code_ >= bound);  // all ones for a 1
    const std::uint32_t up = p + (((1u << probability_bits) - p) >> shift), down = p - (p >> shift);
    code_ -= bound & one;
    range_ = bound + ((range_ - 2u * bound) & one);  // range - bound for a 1, bound for a 0
    p = static_cast<std::uint16_t>(up + ((down - up) & one));
    if (range_ < range_top) {
      range_ <<= 8;
      code_ = (code_ << 8) | next_byte();
    }
    return static_cast<int>(one & 1u);
  }
  int bypass() {
    range_ >>= 1;
    const int b = code_ >= range_;
    code_ -= range_ & (0u - static_cast<std::uint32_t>(b));  // branch-free, as bit_at_rate
    normalise();
    return b;
  }
  std::uint32_t bypass_bits(int count) {
    range_ >>= count;
    std::uint32_t v = code_ / range_;
    const std::uint32_t top = (1u << count) - 1u;
    if (v > top) v = top;  // only a damaged stream gets here
    code_ -= v * range_;
    normalise();
    return v;
  }
  // Bytes read beyond the end. finish() leaves out trailing zero bytes, so a complete
  // stream may need up to 4 (the width of the code register); more means it was cut
  // short. A finish_flushed() stream needs none.
  std::size_t overrun() const noexcept { return overrun_; }
  bool truncated() const noexcept { return overrun_ > 4; }

 private:
  std::uint32_t next_byte() {
    if (next_ != end_) return *next_++;
    ++overrun_;
    return 0;
  }
  void normalise() {
    while (range_ < range_top) {
      range_ <<= 8;
      code_ = (code_ << 8) | next_byte();
    }
  }

  // The unread bytes as two pointers: one register fewer than data, size and position in
  // the decoders' inner loops, which run short of them (docs/ebcode.md §6).
  const unsigned char* next_;
  const unsigned char* end_;
  std::size_t overrun_ = 0;
  std::uint32_t code_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t r_ = 1;
};

}  // namespace fest::range_coding

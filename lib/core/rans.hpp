#pragma once
// Static rANS, the table-driven coder of a .vw "static" slab (docs/volwave.md §4, format
// version 3) and of .ebm 2.1's position residuals (docs/ebcode.md §5, GEOM version 3).
// Range asymmetric numeral systems (Duda 2013) in the layout of ryg_rans: a 32-bit state
// kept in [2^16, 2^32), renormalised by 16-bit words, probabilities in units of 1/2^11.
// The symbol frequencies of every context are counted by the encoder, stored with the slab
// (write_tables) and fixed for the whole slab, so decoding one symbol is one table lookup,
// a multiply and an add -- no adaptation, no division and no branch on the symbol (the
// adaptive binary coder needs one decision per bit of a unary exponent, and the control
// flow must follow each outcome).
//
// The encoder codes symbols in reverse order (rANS is a stack); the decoder reads them
// forward. Reading past the end yields zero words and done() is false, so a truncated or
// corrupt stream never reads outside its bytes; done() also checks that the decoder
// ended in the encoder's initial state, which a damaged stream almost never does.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/bit_stream.hpp"

namespace fest::range_coding {

constexpr int kRansBits = 11;
constexpr std::uint32_t kRansTotal = 1u << kRansBits;  // the frequencies of a table sum to this
constexpr std::uint32_t kRansLow = 1u << 16;           // the state's lower bound
constexpr int kRansAlphabet = 128;                     // symbols 0..127
// A coder may state a lower precision: frequencies in units of 1/2^bits, bits in
// [kRansMinBits, kRansBits]. A decoding table has 2^bits entries, so a stream of a few
// hundred symbols over a dozen contexts (a small slab) need not fill 2048 entries per
// context to read them (docs/volwave.md §4, format version 5). Every step stays one
// lookup, a multiply and an add, and still renormalises by at most one word: after a
// step the state is >= 2^(16 - bits) >= 2^5, so one 16-bit shift restores >= 2^16.
constexpr int kRansMinBits = 5;

// One context's frequencies: freq[s] >= 1 for every symbol the slab codes in it, the sum
// kRansTotal (2^bits); cum[s] = freq[0] + ... + freq[s - 1]. Only the entries below the
// table's alphabet are set (by normalise_table and read_tables): a decoder reads three
// dozen tables per slab, and zeroing 128 entries of each was 4 % of a small volume's
// decode.
struct RansTable {
  RansTable() noexcept {}  // user-provided: a vector of tables is not zero-filled first
  std::array<std::uint16_t, kRansAlphabet> freq;
  std::array<std::uint16_t, kRansAlphabet> cum;
  int implied = 0;  // the symbol whose frequency is 2^bits minus the others'
};

// Counts -> a RansTable whose frequencies (summing to 2^bits) can be written by
// write_tables (at most four significant bits each, except the largest, which the reader
// infers from the sum). Returns false when no such table exists (more used symbols than
// the precision has room for; the caller then codes another way).
bool normalise_table(const std::uint32_t* counts, int alphabet, RansTable& out, int bits = kRansBits);

// The tables of a slab, written as bits: per table the used symbols (gaps, Elias gamma),
// which one has the implied frequency, and the others' frequencies (bit length in four
// bits, then up to three bits below the leading one).
void write_tables(BitWriter& w, const std::vector<RansTable>& tables, const std::vector<int>& alphabets);
// Reads them back; false for a description no encoder writes (a symbol past the
// alphabet, frequencies that do not sum to 2^bits, reading past the end).
bool read_tables(BitReader& r, std::vector<RansTable>& tables, const std::vector<int>& alphabets,
                 int bits = kRansBits);

class RansEncoder {
 public:
  explicit RansEncoder(int bits = kRansBits) : bits_(bits) {}
  // Pushes one symbol with the interval [cum, cum + freq) of 2^bits (freq >= 1).
  void put(std::uint32_t cum, std::uint32_t freq) {
    const std::uint64_t x_max = (std::uint64_t{kRansLow >> bits_} << 16) * freq;
    if (x_ >= x_max) {
      words_.push_back(static_cast<std::uint16_t>(x_));
      x_ >>= 16;
    }
    x_ = ((x_ / freq) << bits_) + (x_ % freq) + cum;
  }
  // The final state (4 bytes, little endian), then the words in the order the decoder
  // reads them.
  std::string finish() const {
    std::string out;
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((x_ >> (8 * i)) & 0xFF));
    for (auto it = words_.rbegin(); it != words_.rend(); ++it) {
      out.push_back(static_cast<char>(*it & 0xFF));
      out.push_back(static_cast<char>(*it >> 8));
    }
    return out;
  }

 private:
  int bits_;
  std::uint32_t x_ = kRansLow;
  std::vector<std::uint16_t> words_;
};

// A decoding table: 2^bits entries per context (as many as the frequencies sum to),
// entry = symbol | freq << 7 | (slot - cum) << 19, so one load gives all a step needs.
using RansEntry = std::uint32_t;
void fill_decode_table(const RansTable& t, int alphabet, RansEntry* out);
// The table of a context that has no symbols: symbol 0 with frequency 2^bits, a step
// that leaves the state as it is (a damaged stream that reaches such a context decodes
// zeros and fails the final check instead of reading an unfilled table).
const RansEntry* identity_decode_table(int bits = kRansBits);

class RansDecoder {
 public:
  // Reads `bytes` in place (they must outlive the decoder). The renormalisation reads a
  // word without a test: at or past the end it reads the stream's last word again (or a
  // zero-padded copy of a stream shorter than a word). A valid stream never uses such a
  // word -- the decoder reads exactly the words the encoder wrote -- and one that does
  // has moved its position past the end, so done() is false.
  explicit RansDecoder(std::string_view bytes, int bits = kRansBits)
      : n_(bytes.size()), last_word_(n_ >= 2 ? n_ - 2 : 0), bits_(bits), slot_mask_((1u << bits) - 1) {
    p_ = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (n_ < 2) {
      for (std::size_t i = 0; i < n_; ++i) short_[i] = p_[i];
      p_ = short_;
    }
    for (std::size_t i = 0; i < 4 && i < n_; ++i) x_ |= static_cast<std::uint32_t>(p_[i]) << (8 * i);
    pos_ = 4;
  }
  RansDecoder(const RansDecoder&) = delete;  // p_ may point into the object itself
  RansDecoder& operator=(const RansDecoder&) = delete;
  __attribute__((always_inline)) int get(const RansEntry* table) {
    const RansEntry e = table[x_ & slot_mask_];
    x_ = ((e >> 7) & 0xFFF) * (x_ >> bits_) + (e >> 19);
    renormalise();
    return static_cast<int>(e & 0x7F);
  }
  // A binary symbol whose 0 has frequency f0 (0..2^bits), without a table: 1 when the
  // slot lies at or above f0. f0 = 2^bits (or 0) leaves the state as it is.
  __attribute__((always_inline)) int get_bit(std::uint32_t f0) {
    const std::uint32_t slot = x_ & slot_mask_;
    const bool one = slot >= f0;
    const std::uint32_t freq = one ? slot_mask_ + 1 - f0 : f0;
    const std::uint32_t bias = one ? slot - f0 : slot;
    x_ = freq * (x_ >> bits_) + bias;
    renormalise();
    return static_cast<int>(one);
  }
  // Every word read, none missing, and the state back where the encoder started.
  bool done() const noexcept { return pos_ == n_ && x_ == kRansLow; }

 private:
  // Without a branch on the data: at most one word (freq <= 2^11 keeps the state >= 2^5
  // before it, so one 16-bit shift restores >= 2^16).
  __attribute__((always_inline)) void renormalise() {
    const std::size_t at = pos_ < last_word_ ? pos_ : last_word_;
    const std::uint32_t w = static_cast<std::uint32_t>(p_[at] | (p_[at + 1] << 8));
    const bool need = x_ < kRansLow;
    x_ = need ? (x_ << 16) | w : x_;
    pos_ += need ? 2 : 0;
  }
  const std::uint8_t* p_ = nullptr;
  std::uint8_t short_[2] = {0, 0};
  std::size_t n_, last_word_;
  int bits_;
  std::uint32_t slot_mask_;
  std::size_t pos_ = 0;
  std::uint32_t x_ = 0;
};

}  // namespace fest::range_coding

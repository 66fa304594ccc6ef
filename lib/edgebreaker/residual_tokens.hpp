#pragma once
// GEOM version 3 (.ebm 2.1; docs/ebcode.md §5, ebm(5)): every coordinate's position
// residual r is ONE token of a static rANS alphabet -- k, the bit length of |r| (0..qp),
// together with the two bits of |r| below its leading one (those that exist) -- coded with
// per-context frequency tables that the encoder counts in a first pass and stores in the
// section (core/rans.hpp's description: Elias-gamma gaps, four significant bits), and the
// rest (the sign, then the bits of |r| below those two) in a plain bit stream. Decoding a
// coordinate is a table lookup, a multiply and a read of raw bits, with no branch on the
// data: GEOM version 2's adaptive binary decisions ("same length?", side, unary steps)
// cost about 2.8 mispredicted branches per coordinate, which set ebdecode's speed
// (docs/ebcode.md §6). Draco codes a residual as one rANS symbol too.
//
// The context of a token is the bit length of the previous residual on the same axis,
// with one table per length shared by the three axes. Measured on the bench meshes
// (docs/ebcode.md §6): richer contexts (the axis, the coordinate coded just before, both
// lengths) lower the entropy by less than their extra tables cost, and the two bits below
// the leading one in the token save about 1 % over raw bits.

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/rans.hpp"

namespace fest::edgebreaker {

// A token's context: k of the previous residual on its axis (0 at the start), which is
// also the index of its table (bits + 1 tables).
struct TokenContexts {
  std::array<int, 3> previous{};
  [[gnu::always_inline]] int bucket(int axis) const { return previous[static_cast<std::size_t>(axis)]; }
  [[gnu::always_inline]] void update(int axis, int k) { previous[static_cast<std::size_t>(axis)] = k; }
};

// What a token stands for: |r| = lead | (the raw bits above the sign), with `raw` raw bits
// after the token (the sign first; none for r = 0), and k the bit length of |r|.
struct TokenShape {
  std::uint32_t lead = 0;
  std::uint8_t k = 0, raw = 0;
};
// Tokens: 0 (r = 0), 1 (|r| = 1), 2 and 3 (|r| = 2, 3), then for k >= 3 four per length,
// 4 + 4 (k - 3) + the two bits below the leading one. The alphabet for `bits` (1..30).
int token_alphabet(int bits);
TokenShape token_shape(int token);

// `residuals` holds x, y, z per coded vertex, each wrapped into the quantisation range of
// `bits` (1..30): |r| <= 2^(bits - 1). Nothing when a table cannot be described
// (range_coding::normalise_table); the caller then keeps GEOM version 2.
std::optional<std::string> encode_residual_tokens(const std::vector<std::int64_t>& residuals, int bits);

// The decoder's state while it runs: plain values, copied into the decoding loop so that
// GCC keeps them in registers (a decoder whose address escapes to a call is kept in
// memory; docs/ebcode.md §6). The rANS step is core/rans.hpp's RansDecoder::get, written
// out here on that state.
struct ResidualTokenReader {
  const range_coding::RansEntry* const* table;  // per context
  const TokenShape* shapes;                     // per token
  TokenContexts contexts;
  std::uint32_t x;                 // the rANS state
  const std::uint8_t* words;       // the rANS stream, two zero bytes after it
  std::size_t word_pos, word_end;  // its next unread byte, its length
  const std::uint8_t* raw;         // the bit stream, eight zero bytes after it
  std::uint64_t bit_pos, bit_end;  // its next unread bit, its length in bits

  // The residual of the next coordinate, on `axis` (0, 1, 2 in turn).
  [[gnu::always_inline]] std::int64_t get(int axis) {
    const range_coding::RansEntry e = table[contexts.bucket(axis)][x & (range_coding::kRansTotal - 1)];
    x = ((e >> 7) & 0xFFFu) * (x >> range_coding::kRansBits) + (e >> 19);
    // At most one 16-bit word (core/rans.hpp); past the end the zeros after the stream.
    const std::size_t at = word_pos < word_end ? word_pos : word_end;
    const std::uint32_t w = static_cast<std::uint32_t>(words[at] | (words[at + 1] << 8));
    const bool need = x < range_coding::kRansLow;
    x = need ? (x << 16) | w : x;
    word_pos += need ? 2 : 0;
    const TokenShape shape = shapes[e & 0x7Fu];
    contexts.update(axis, shape.k);
    // The raw bits: the sign, then the bits of |r| below the token's.
    std::uint64_t word;
    std::memcpy(&word, raw + ((bit_pos < bit_end ? bit_pos : bit_end) >> 3), 8);
    const std::uint64_t bits = (word >> (bit_pos & 7u)) & ((std::uint64_t{1} << shape.raw) - 1u);
    bit_pos += shape.raw;
    const std::uint64_t magnitude = shape.lead | (bits >> 1);
    const std::uint64_t negative = bits & 1u;
    return static_cast<std::int64_t>((magnitude ^ (0u - negative)) + negative);
  }
  // Every rANS word read and the state back where the encoder started (a damaged stream
  // almost never ends there), every raw bit read and no more than the last byte's padding
  // left.
  bool complete() const noexcept {
    return word_pos == word_end && x == range_coding::kRansLow && bit_pos <= bit_end && bit_end - bit_pos < 8;
  }
};

// Reads what encode_residual_tokens wrote: the constructor reads the tables (bad_input
// when they are not a description the encoder writes) and owns the decoding tables and
// padded copies of the streams that reader() points into. Nothing is read outside them.
class ResidualTokenDecoder {
 public:
  ResidualTokenDecoder(std::string_view section, int bits);
  ResidualTokenReader reader() const noexcept { return start_; }

 private:
  std::vector<const range_coding::RansEntry*> table_;
  std::unique_ptr<range_coding::RansEntry[]> storage_;
  std::unique_ptr<std::uint8_t[]> words_, raw_;
  std::array<TokenShape, range_coding::kRansAlphabet> shapes_{};
  ResidualTokenReader start_{};
};

}  // namespace fest::edgebreaker

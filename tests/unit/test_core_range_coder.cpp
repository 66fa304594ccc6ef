// lib/core/range_coder.hpp: both endings decode what was coded, and the shortest ending
// is never longer than the flushed one less its first byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/range_coder.hpp"
#include "core/rng.hpp"

using fest::range_coding::RangeDecoder;
using fest::range_coding::RangeEncoder;

namespace {

struct Symbol {
  int kind;  // 0 adaptive bit, 1 bypass bit, 2 four bypass bits, 3 frequency symbol
  std::uint32_t value;
};

std::vector<Symbol> mixed_symbols(std::uint64_t seed, std::size_t n) {
  fest::Rng rng(seed);
  std::vector<Symbol> s;
  for (std::size_t i = 0; i < n; ++i) {
    const int kind = static_cast<int>(rng.below(4));
    const std::uint32_t v = kind == 0 ? (rng.below(10) < 8 ? 0u : 1u)  // skewed: the model adapts
                            : kind == 1 ? static_cast<std::uint32_t>(rng.below(2))
                            : kind == 2 ? static_cast<std::uint32_t>(rng.below(16))
                                        : static_cast<std::uint32_t>(rng.below(3));
    s.push_back({kind, v});
  }
  return s;
}

// Frequencies 5, 2, 1 of 8 for the symbol kind.
constexpr std::uint32_t kCum[] = {0, 5, 7}, kFreq[] = {5, 2, 1}, kTotal = 8;

void encode(RangeEncoder& enc, const std::vector<Symbol>& symbols) {
  std::uint16_t p = fest::range_coding::probability_half;
  for (const Symbol& s : symbols) {
    if (s.kind == 0) enc.bit(p, static_cast<int>(s.value));
    else if (s.kind == 1) enc.bypass(static_cast<int>(s.value));
    else if (s.kind == 2) enc.bypass_bits(s.value, 4);
    else enc.encode(kCum[s.value], kFreq[s.value], kTotal);
  }
}

std::vector<Symbol> decode(RangeDecoder& dec, const std::vector<Symbol>& kinds) {
  std::uint16_t p = fest::range_coding::probability_half;
  std::vector<Symbol> out;
  for (const Symbol& k : kinds) {
    std::uint32_t v = 0;
    if (k.kind == 0) v = static_cast<std::uint32_t>(dec.bit(p));
    else if (k.kind == 1) v = static_cast<std::uint32_t>(dec.bypass());
    else if (k.kind == 2) v = dec.bypass_bits(4);
    else {
      const std::uint32_t t = dec.target(kTotal);
      v = t < 5 ? 0 : t < 7 ? 1 : 2;
      dec.consume(kCum[v], kFreq[v]);
    }
    out.push_back({k.kind, v});
  }
  return out;
}

bool same(const std::vector<Symbol>& a, const std::vector<Symbol>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].kind != b[i].kind || a[i].value != b[i].value) return false;
  return true;
}

}  // namespace

TEST(CoreRangeCoder, BothEndingsRoundTrip) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::vector<Symbol> symbols = mixed_symbols(seed, 3000);
    RangeEncoder shortest, flushed;
    encode(shortest, symbols);
    encode(flushed, symbols);
    const std::string a = shortest.finish(), b = flushed.finish_flushed();
    ASSERT_FALSE(b.empty());
    EXPECT_EQ(b[0], '\0');  // LZMA's first byte: no carry reaches it
    EXPECT_LE(a.size(), b.size() - 1);
    RangeDecoder da(a), db(b, RangeDecoder::FirstByte::stored);
    EXPECT_TRUE(same(decode(da, symbols), symbols)) << "seed " << seed;
    EXPECT_TRUE(same(decode(db, symbols), symbols)) << "seed " << seed;
    EXPECT_FALSE(da.truncated());
    EXPECT_EQ(db.overrun(), 0u);  // a flushed stream holds every byte the decoder reads
  }
}

TEST(CoreRangeCoder, CutStreamsAreSeenAsOverrun) {
  const std::vector<Symbol> symbols = mixed_symbols(7, 4000);
  RangeEncoder enc;
  encode(enc, symbols);
  const std::string bytes = enc.finish();
  RangeDecoder dec(std::string_view(bytes).substr(0, bytes.size() / 2));
  decode(dec, symbols);
  EXPECT_TRUE(dec.truncated());
}

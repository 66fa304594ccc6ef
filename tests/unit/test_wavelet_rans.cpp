// Static rANS of the .vw static slabs (lib/wavelet/rans.hpp, docs/volwave.md §4): the
// coder and its table description round-trip, damage is seen, and a slab coded either
// way decodes to the same coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "wavelet/band_coder.hpp"
#include "wavelet/rans.hpp"

using namespace fest;
using namespace fest::wavelet;

namespace {

// Symbols of a few skewed distributions, each event (table, symbol).
struct Events {
  std::vector<std::uint32_t> counts[3];
  std::vector<std::pair<int, int>> seq;
};

Events make_events(std::size_t n, std::uint64_t seed) {
  Events ev;
  for (auto& c : ev.counts) c.assign(kRansAlphabet, 0);
  std::mt19937_64 rng(seed);
  std::geometric_distribution<int> g0(0.5), g1(0.05);
  for (std::size_t i = 0; i < n; ++i) {
    const int t = static_cast<int>(rng() % 3);
    int s = t == 0 ? std::min(g0(rng), kRansAlphabet - 1) : t == 1 ? std::min(g1(rng), kRansAlphabet - 1) : 77;
    ev.seq.push_back({t, s});
    ++ev.counts[t][static_cast<std::size_t>(s)];
  }
  return ev;
}

}  // namespace

TEST(WaveletRans, TablesAndSymbolsRoundTrip) {
  const Events ev = make_events(20000, 3);
  std::vector<RansTable> tables(4);  // the fourth stays empty
  const std::vector<int> alphabets{kRansAlphabet, kRansAlphabet, kRansAlphabet, 2};
  for (int t = 0; t < 3; ++t) ASSERT_TRUE(normalise_table(ev.counts[t].data(), kRansAlphabet, tables[static_cast<std::size_t>(t)]));
  const std::uint32_t no_counts[2] = {0, 0};
  ASSERT_TRUE(normalise_table(no_counts, 2, tables[3]));
  // Every table sums to kRansTotal, every coded symbol keeps a frequency >= 1.
  for (int t = 0; t < 3; ++t) {
    std::uint32_t sum = 0;
    for (int s = 0; s < kRansAlphabet; ++s) {
      sum += tables[static_cast<std::size_t>(t)].freq[static_cast<std::size_t>(s)];
      if (ev.counts[t][static_cast<std::size_t>(s)]) {
        EXPECT_GE(tables[static_cast<std::size_t>(t)].freq[static_cast<std::size_t>(s)], 1);
      }
    }
    EXPECT_EQ(sum, kRansTotal);
  }
  BitWriter w;
  write_tables(w, tables, alphabets);
  const std::string desc = w.finish();
  BitReader r(desc);
  std::vector<RansTable> back;
  ASSERT_TRUE(read_tables(r, back, alphabets));
  for (std::size_t t = 0; t < tables.size(); ++t)
    for (int s = 0; s < alphabets[t]; ++s) {  // the entries a table's alphabet has
      EXPECT_EQ(back[t].freq[static_cast<std::size_t>(s)], tables[t].freq[static_cast<std::size_t>(s)]) << t;
      EXPECT_EQ(back[t].cum[static_cast<std::size_t>(s)], tables[t].cum[static_cast<std::size_t>(s)]) << t;
    }
  RansEncoder enc;
  for (auto it = ev.seq.rbegin(); it != ev.seq.rend(); ++it) {
    const RansTable& tab = tables[static_cast<std::size_t>(it->first)];
    enc.put(tab.cum[static_cast<std::size_t>(it->second)], tab.freq[static_cast<std::size_t>(it->second)]);
  }
  const std::string bytes = enc.finish();
  std::vector<RansEntry> dtab(3 * kRansTotal);
  for (int t = 0; t < 3; ++t) fill_decode_table(back[static_cast<std::size_t>(t)], kRansAlphabet, dtab.data() + t * kRansTotal);
  RansDecoder dec(bytes);
  for (std::size_t i = 0; i < ev.seq.size(); ++i) {
    // The identity table between symbols changes nothing (the sign of a zero).
    ASSERT_EQ(dec.get(identity_decode_table()), 0);
    ASSERT_EQ(dec.get(dtab.data() + ev.seq[i].first * kRansTotal), ev.seq[i].second) << i;
  }
  EXPECT_TRUE(dec.done());
  // The entropy bound: within 1 % of the empirical entropy plus the 4-byte state.
  double bits = 0;
  for (int t = 0; t < 3; ++t) {
    double n = 0;
    for (auto c : ev.counts[t]) n += c;
    for (auto c : ev.counts[t])
      if (c) bits -= c * std::log2(c / n);
  }
  EXPECT_LT(8.0 * static_cast<double>(bytes.size()), 1.01 * bits + 32 + 16);
  // A cut stream is seen.
  RansDecoder cut(std::string_view(bytes).substr(0, bytes.size() / 2));
  for (std::size_t i = 0; i < ev.seq.size(); ++i) (void)cut.get(dtab.data() + ev.seq[i].first * kRansTotal);
  EXPECT_FALSE(cut.done());
}

TEST(WaveletRans, BadTableDescriptionsAreRefused) {
  const std::vector<int> alphabets{2};
  {  // a symbol past a binary alphabet: 2 symbols, gaps 1 and 2 (symbols 0 and 2)
    BitWriter w;
    w.put(0b011, 3);   // gamma(3): 2 used
    w.put(0b0, 1);     // gamma(1): symbol 0
    w.put(0b001, 3);   // gamma(2): symbol 2
    const std::string b = w.finish();
    BitReader r(b);
    std::vector<RansTable> t;
    EXPECT_FALSE(read_tables(r, t, alphabets));
  }
  {  // an empty description runs past its end
    BitReader r(std::string_view{});
    std::vector<RansTable> t;
    EXPECT_FALSE(read_tables(r, t, alphabets));
  }
}

TEST(WaveletRans, SlabDecodesTheSameEitherWay) {
  // A detail band with Laplacian coefficients and a zero region: coded adaptively and
  // with static tables, both decode to the input; the static coding is chosen by size.
  const Dims dims{32, 32, 16};
  const auto bands = subbands(dims, 1);
  std::vector<std::int64_t> data(dims[0] * dims[1] * dims[2]);
  std::mt19937_64 rng(9);
  std::exponential_distribution<double> ex(0.15);
  for (std::size_t i = 0; i < data.size(); ++i) {
    const auto m = static_cast<std::int64_t>(ex(rng));
    data[i] = (i % dims[0]) > 24 ? 0 : (rng() & 1 ? m : -m);
  }
  for (const auto& band : bands) {
    const Subband* parent = parent_of(bands, band);
    for (const auto& slab : slabs_of(band)) {
      for (SlabCoding coding : {SlabCoding::adaptive, SlabCoding::fixed, SlabCoding::smaller}) {
        const std::string bytes = encode_slab(data.data(), dims, band, parent, slab, coding);
        ASSERT_FALSE(bytes.empty());
        if (coding != SlabCoding::smaller) {
          EXPECT_EQ(bytes[0], coding == SlabCoding::fixed ? 1 : 0);
        }
        std::vector<std::int64_t> out(data.size(), 0);
        // The parent band must be there already, as in decode_vw (coarse to fine).
        if (parent)
          for (std::size_t z = parent->lo[2]; z < parent->hi[2]; ++z)
            for (std::size_t y = parent->lo[1]; y < parent->hi[1]; ++y)
              for (std::size_t x = parent->lo[0]; x < parent->hi[0]; ++x) {
                const std::size_t i = x + dims[0] * (y + dims[1] * z);
                out[i] = data[i];
              }
        decode_slab(bytes, out.data(), dims, band, parent, slab, 40);
        for (std::size_t z = slab.z0; z < slab.z1; ++z)
          for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y)
            for (std::size_t x = band.lo[0]; x < band.hi[0]; ++x) {
              const std::size_t i = x + dims[0] * (y + dims[1] * z);
              ASSERT_EQ(out[i], data[i]) << band.level << " " << band.orientation << " " << x << "," << y << "," << z;
            }
        // Damage in the streams is refused as bad input, never trusted blindly.
        std::string cut = bytes.substr(0, bytes.size() - 3);
        std::vector<std::int64_t> junk(data.size(), 0);
        EXPECT_THROW(decode_slab(cut, junk.data(), dims, band, parent, slab, 40), Error);
      }
    }
  }
}

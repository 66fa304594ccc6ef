// The range coder (docs/ebcode.md §4): long random streams of multi-symbol, adaptive-bit and bypass
// decisions come back exactly, including the carry path through runs of 0xFF bytes.
#include <gtest/gtest.h>

#include <random>

#include "edgebreaker/range_coder.hpp"

namespace {

using namespace fest::edgebreaker;

struct Decision {
  int kind;  // 0 multi-symbol, 1 adaptive bit, 2 bypass
  std::uint32_t value, total;
};

std::string round_trip(const std::vector<Decision>& ds, const std::vector<std::uint32_t>& freq) {
  std::uint32_t total = 0;
  std::vector<std::uint32_t> cum;
  for (auto f : freq) {
    cum.push_back(total);
    total += f;
  }
  RangeEncoder enc;
  std::uint16_t p[4] = {probability_half, probability_half, probability_half, probability_half};
  for (const Decision& d : ds) {
    if (d.kind == 0) enc.encode(cum[d.value], freq[d.value], total);
    else if (d.kind == 1) enc.bit(p[d.total & 3], static_cast<int>(d.value));
    else enc.bypass(static_cast<int>(d.value));
  }
  const std::string bytes = enc.finish();
  RangeDecoder dec(bytes);
  std::uint16_t q[4] = {probability_half, probability_half, probability_half, probability_half};
  for (std::size_t i = 0; i < ds.size(); ++i) {
    const Decision& d = ds[i];
    std::uint32_t got;
    if (d.kind == 0) {
      const std::uint32_t t = dec.target(total);
      got = static_cast<std::uint32_t>(std::upper_bound(cum.begin(), cum.end(), t) - cum.begin() - 1);
      dec.consume(cum[got], freq[got]);
    } else if (d.kind == 1) {
      got = static_cast<std::uint32_t>(dec.bit(q[d.total & 3]));
    } else {
      got = static_cast<std::uint32_t>(dec.bypass());
    }
    EXPECT_EQ(got, d.value) << "decision " << i;
    if (got != d.value) break;
  }
  EXPECT_FALSE(dec.truncated());
  return bytes;
}

TEST(EdgebreakerRangeCoder, RandomMixedStreamsRoundTrip) {
  std::mt19937 rng(7);
  const std::vector<std::uint32_t> freq{1, 7, 30000, 500, 2, 2268};  // total 32768
  std::discrete_distribution<int> pick({1, 7, 30000, 500, 2, 2268});
  std::vector<Decision> ds;
  for (int i = 0; i < 1000000; ++i) {
    const int kind = static_cast<int>(rng() % 3);
    if (kind == 0) ds.push_back({0, static_cast<std::uint32_t>(pick(rng)), 0});
    else if (kind == 1) ds.push_back({1, (rng() % 10) < 8 ? 0u : 1u, static_cast<std::uint32_t>(rng())});
    else ds.push_back({2, static_cast<std::uint32_t>(rng() & 1u), 0});
  }
  round_trip(ds, freq);
}

// Bypass ones drive low towards the top of its range, so the encoder holds long runs of
// pending 0xFF bytes (the cache/pending path that a carry resolves); the multi-symbol
// decisions in between move low across byte boundaries with runs pending.
TEST(EdgebreakerRangeCoder, CarryThroughLongFFRuns) {
  const std::vector<std::uint32_t> freq{65000, 536};
  std::vector<Decision> ds;
  for (int round = 0; round < 200; ++round) {
    for (int i = 0; i < 40 + round; ++i) ds.push_back({2, 1, 0});
    ds.push_back({0, 1, 0});
    ds.push_back({0, 0, 0});
  }
  const std::string bytes = round_trip(ds, freq);
  EXPECT_NE(bytes.find(std::string(4, '\xff')), std::string::npos);
}

}  // namespace

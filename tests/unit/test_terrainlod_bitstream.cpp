// The tile body's bit packing (terrainlod/bitstream.hpp) against a plain bit-by-bit
// model of the format: LSB-first within bytes, the last byte padded with zeros, Rice codes
// as unary quotient + terminating zero + k low bits, escapes as 24 ones + 7-bit width +
// the value's bits.

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/bitstream.hpp"

namespace {

using namespace fest::terrainlod;

struct BitModel {
  std::vector<bool> bits;
  void put(std::uint64_t v, int n) {
    for (int b = 0; b < n; ++b) bits.push_back(((v >> b) & 1) != 0);
  }
  void put_rice(std::uint64_t v, int k) {
    const std::uint64_t q = v >> k;
    if (q >= kRiceEscape) {
      put(~std::uint64_t{0}, kRiceEscape);
      put(static_cast<std::uint64_t>(bit_width(v)), 7);
      put(v, bit_width(v));
      return;
    }
    for (std::uint64_t i = 0; i < q; ++i) bits.push_back(true);
    bits.push_back(false);
    put(v, k);
  }
  std::string bytes() const {
    std::string out((bits.size() + 7) / 8, '\0');
    for (std::size_t i = 0; i < bits.size(); ++i)
      if (bits[i]) out[i / 8] = static_cast<char>(static_cast<unsigned char>(out[i / 8]) | (1u << (i % 8)));
    return out;
  }
};

TEST(TerrainlodBitstream, MatchesTheBitByBitModelAndReadsBack) {
  std::mt19937_64 rng(5);
  struct Op {
    bool rice;
    std::uint64_t v;
    int n;
  };
  for (int trial = 0; trial < 50; ++trial) {
    BitWriter w;
    BitModel m;
    std::vector<Op> ops;
    for (int i = 0; i < 400; ++i) {
      const bool rice = rng() % 2 == 0;
      const int n = static_cast<int>(rng() % 65);  // 0..64 bits, or the Rice k
      std::uint64_t v = rng() >> (rng() % 64);
      if (rice) {
        const int k = n % 41;
        v >>= rng() % 64;  // mostly small values, some escapes
        w.put_rice(v, k), m.put_rice(v, k);
        ops.push_back({true, v, k});
      } else {
        if (n < 64) v &= (std::uint64_t{1} << n) - 1;
        w.put(v, n), m.put(v, n);
        ops.push_back({false, v, n});
      }
    }
    const std::string bytes = w.take();
    ASSERT_EQ(bytes, m.bytes()) << "trial " << trial;
    BitReader r(bytes, "test");
    for (const Op& op : ops) ASSERT_EQ(op.rice ? r.get_rice(op.n) : r.get(op.n), op.v);
  }
}

TEST(TerrainlodBitstream, ReadingPastTheEndIsBadInput) {
  BitWriter w;
  w.put_rice(5, 1);  // 110 1: four bits
  const std::string bytes = w.take();
  BitReader r(bytes, "test");
  EXPECT_EQ(r.get_rice(1), 5u);
  EXPECT_EQ(r.get(4), 0u);  // the padding of the one byte
  EXPECT_THROW(r.get(1), fest::Error);
  const std::string ones(2, '\xff');  // a quotient that never ends
  BitReader q(ones, "test");
  EXPECT_THROW(q.get_rice(0), fest::Error);
  const std::string escape(3, '\xff');  // an escape whose width is cut off
  BitReader e(escape, "test");
  EXPECT_THROW(e.get_rice(0), fest::Error);
}

}  // namespace

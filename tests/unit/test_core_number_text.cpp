// append_g17 / append_int against the C library's printf, the independent reference:
// the same bytes for every kind of double (subnormals, powers of ten at the switch
// between fixed and exponent form, halfway cases, random bit patterns).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

#include "core/number_text.hpp"

namespace {

std::string printf_g17(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string g17(double x) {
  std::string s;
  fest::append_g17(s, x);
  return s;
}

TEST(NumberText, G17MatchesPrintfOnSpecialValues) {
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1e-5, 1e-4, 9.9999999999999995e-5, 1e16, 1e17, 1e-300,
                           123456789012345678.0, 38.0, 0.30000000000000004, 2.5e-310,
                           std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::epsilon()};
  for (double x : values) EXPECT_EQ(g17(x), printf_g17(x)) << x;
}

TEST(NumberText, G17MatchesPrintfOnRandomBitPatterns) {
  std::mt19937_64 rng(20261128);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    ASSERT_EQ(g17(x), printf_g17(x)) << bits;
    ++checked;
  }
  EXPECT_GT(checked, 190000);
}

TEST(NumberText, G17MatchesPrintfOnOrdinaryMagnitudes) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 100000; ++i) {
    const double x = u(rng) * std::pow(10.0, static_cast<int>(rng() % 12) - 6);
    ASSERT_EQ(g17(x), printf_g17(x)) << x;
  }
}

TEST(NumberText, G17MatchesPrintfAcrossTheFastRangeAndItsEdges) {
  // Every decade from 1e-20 to 1e20 (the 128-bit path covers 1e-16..1e17), values next
  // to powers of ten (where log10 misleads), and exact halfway cases at the 17th digit
  // (doubles in [2^50, 2^51) are multiples of 1/4: .25 and .75 have 18 digits).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(1.0, 10.0);
  for (int d = -20; d <= 20; ++d) {
    const double p10 = std::pow(10.0, d);
    for (double x : {p10, std::nextafter(p10, 0.0), std::nextafter(p10, 1e300)}) {
      ASSERT_EQ(g17(x), printf_g17(x)) << x;
      ASSERT_EQ(g17(-x), printf_g17(-x)) << x;
    }
    for (int i = 0; i < 5000; ++i) {
      const double x = u(rng) * p10;
      ASSERT_EQ(g17(x), printf_g17(x)) << x;
    }
  }
  for (double base : {1125899906842624.0, 1125899906842625.0, 2000000000000000.0, 2251799813685247.0})
    for (double frac : {0.25, 0.5, 0.75}) ASSERT_EQ(g17(base + frac), printf_g17(base + frac)) << base + frac;
  for (double x : {9.99999999999999999e-5, 0.0001, 99999999999999999.0, 1e17, 0.99999999999999994, 1.5e-16})
    EXPECT_EQ(g17(x), printf_g17(x)) << x;
}

TEST(NumberText, G17MatchesPrintfOnRandomSignificandsInAndAroundTheFastRange) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 400000; ++i) {
    const std::uint64_t exponent = 1023 - 60 + rng() % 120;  // 2^-60 .. 2^60
    const std::uint64_t bits = (rng() & ((1ull << 52) - 1)) | (exponent << 52) | (rng() & 1ull) << 63;
    double x;
    std::memcpy(&x, &bits, sizeof x);
    ASSERT_EQ(g17(x), printf_g17(x)) << bits;
  }
}

TEST(NumberText, IntegersAndAppending) {
  std::string s = "a";
  fest::append_int(s, 0);
  s += ',';
  fest::append_int(s, -42);
  s += ',';
  fest::append_int(s, std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(s, "a0,-42,-9223372036854775808");
}

}  // namespace

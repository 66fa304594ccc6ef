// lib/core/little_endian.hpp: values read back as written, LEB128 as specified, and
// running out reported through the caller's Errors with the bytes needed and where.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/little_endian.hpp"

namespace le = fest::little_endian;

namespace {

struct ThrowingErrors {
  [[noreturn]] void truncated(std::size_t n, std::size_t pos) const {
    throw std::runtime_error("needs " + std::to_string(n) + " at " + std::to_string(pos));
  }
  [[noreturn]] void varint_too_long(std::size_t pos) const {
    throw std::runtime_error("varint at " + std::to_string(pos));
  }
};
using Reader = le::Reader<ThrowingErrors>;

}  // namespace

TEST(CoreLittleEndian, ValuesRoundTrip) {
  std::string out;
  le::put_u8(out, 0xAB);
  le::put_u16(out, 0x1234);
  le::put_u32(out, 0xDEADBEEFu);
  le::put_u64(out, 0x0102030405060708ull);
  le::put_f32(out, -1.5f);
  le::put_f64(out, 0.1);
  le::put_varint(out, 300);
  le::put_varint(out, std::numeric_limits<std::uint64_t>::max());
  Reader r(out, ThrowingErrors{});
  EXPECT_EQ(r.u8(), 0xAB);
  EXPECT_EQ(r.u16(), 0x1234);
  EXPECT_EQ(r.u32(), 0xDEADBEEFu);
  EXPECT_EQ(r.u64(), 0x0102030405060708ull);
  EXPECT_EQ(r.f32(), -1.5f);
  EXPECT_EQ(r.f64(), 0.1);
  EXPECT_EQ(r.varint(), 300u);
  EXPECT_EQ(r.varint(), std::numeric_limits<std::uint64_t>::max());
  EXPECT_TRUE(r.done());
}

TEST(CoreLittleEndian, ByteOrderAndLeb128AreTheStandardOnes) {
  std::string out;
  le::put_u32(out, 0x11223344u);
  le::put_varint(out, 300);  // LEB128 of 300: 0xAC 0x02
  EXPECT_EQ(out, std::string("\x44\x33\x22\x11\xAC\x02", 6));
}

TEST(CoreLittleEndian, RunningOutIsTheCallersError) {
  const std::string three("\x01\x02\x03", 3);
  Reader r(three, ThrowingErrors{}, 1);
  EXPECT_EQ(r.left(), 2u);
  try {
    r.u32();
    FAIL() << "read past the end";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "needs 4 at 1");
  }
  const std::string endless(11, '\x80');
  Reader v(endless, ThrowingErrors{});
  try {
    v.varint();
    FAIL() << "an endless varint";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "varint at 10");
  }
}

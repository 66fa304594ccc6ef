#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "formats/gzip.hpp"
#include "formats/input.hpp"

using namespace fest::formats;

namespace {
std::string some_text() {
  std::string s;
  for (int i = 0; i < 10000; ++i) s += "line " + std::to_string(i) + "\n";
  return s;
}
}  // namespace

TEST(Gzip, RoundTrip) {
  const std::string text = some_text();
  const std::string gz = gzip(text);
  EXPECT_TRUE(is_gzip(gz));
  EXPECT_LT(gz.size(), text.size());
  EXPECT_EQ(gunzip(gz), text);
}

TEST(Gzip, ZlibStreamsToo) {
  const std::string text = some_text();
  const std::string z = gzip(text, 6, true);
  EXPECT_FALSE(is_gzip(z));
  EXPECT_EQ(gunzip(z), text);
  EXPECT_EQ(inflate_exact(z, 100), text.substr(0, 100));
}

TEST(Gzip, ConcatenatedMembersFormOneStream) {
  EXPECT_EQ(gunzip(gzip("abc") + gzip("def")), "abcdef");
}

TEST(Gzip, TruncatedAndCorruptDataAreBadInput) {
  const std::string gz = gzip(some_text());
  for (const std::string& bad : {gz.substr(0, gz.size() / 2), gz.substr(0, 12), std::string("\x1f\x8b\x08\x00garbage")}) {
    try {
      gunzip(bad);
      FAIL();
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input);
    }
  }
}

TEST(Gzip, ExpansionBeyondTheLimitIsRefused) {
  // 10 MB of zeros compress to ~10 kB: a small bomb.
  const std::string gz = gzip(std::string(10 << 20, '\0'));
  EXPECT_THROW(gunzip(gz, 1 << 20), fest::Error);
  EXPECT_EQ(gunzip(gz, 11 << 20).size(), 10u << 20);
}

TEST(Gzip, InflateExactNeedsEnoughData) {
  const std::string z = gzip("0123456789", 6, true);
  EXPECT_EQ(inflate_exact(z, 10), "0123456789");
  EXPECT_THROW(inflate_exact(z, 11), fest::Error);
}

TEST(Recognise, GzipIsTransparent) {
  Input in = recognise(gzip("OFF\n0 0 0\n"), "x.off.gz");
  EXPECT_TRUE(in.was_gzip);
  EXPECT_EQ(in.format, Format::off);
  EXPECT_EQ(in.bytes, "OFF\n0 0 0\n");
}

TEST(Recognise, CorruptGzipNamesTheInput) {
  try {
    recognise(std::string("\x1f\x8b\x08\x00zz", 6), "head.nii.gz");
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_NE(std::string(e.what()).find("head.nii.gz"), std::string::npos);
  }
}

// quoted_bytes and json_failure_words (lib/core/quote.hpp): what a message may quote of
// its input. Expected strings are written out by hand from the escaping rule.

#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "core/quote.hpp"

TEST(CoreQuote, PrintableAsciiPassesThrough) {
  EXPECT_EQ(fest::quoted_bytes("vertex 1.5"), "vertex 1.5");
}

TEST(CoreQuote, ControlAndNonUtf8BytesEscaped) {
  EXPECT_EQ(fest::quoted_bytes(std::string("\x10")), "\\x10");
  EXPECT_EQ(fest::quoted_bytes("norm\xe1l"), "norm\\xe1l");         // lone lead byte
  EXPECT_EQ(fest::quoted_bytes(std::string("a\0b\x7f", 4)), "a\\x00b\\x7f");
  EXPECT_EQ(fest::quoted_bytes("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(fest::quoted_bytes("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // surrogate
}

TEST(CoreQuote, WellFormedUtf8Kept) {
  EXPECT_EQ(fest::quoted_bytes("\xce\xb1\xce\xb2"), "\xce\xb1\xce\xb2");  // Greek alpha beta
}

TEST(CoreQuote, TruncatedAfterMaxBytes) {
  const std::string pixels(1234, '\x01');
  const std::string q = fest::quoted_bytes(pixels, 4);
  EXPECT_EQ(q, "\\x01\\x01\\x01\\x01...");
  EXPECT_EQ(fest::quoted_bytes("abcdef", 3), "abc...");
  // A multi-byte character cut by the limit is escaped, not split raw.
  EXPECT_EQ(fest::quoted_bytes("a\xce\xb1", 2), "a\\xce...");
}

TEST(CoreQuote, LineColumn) {
  const auto at = fest::line_column_at("ab\ncd\nef", 7);
  EXPECT_EQ(at.line, 3u);
  EXPECT_EQ(at.column, 2u);
}

TEST(CoreQuote, JsonParseErrorInFestWords) {
  const std::string text = "{\n  \"a\": 1,\n  \"b\": tru\xf4\n}";
  try {
    const auto doc = nlohmann::json::parse(text);
    EXPECT_TRUE(doc.is_null());
    FAIL();
  } catch (const nlohmann::json::parse_error& e) {
    const std::string w = fest::json_failure_words(e.what(), e.byte, text);
    EXPECT_EQ(w.rfind("not JSON: ", 0), 0u) << w;
    EXPECT_NE(w.find("at line 3, column "), std::string::npos) << w;
    EXPECT_NE(w.find("(byte " + std::to_string(e.byte) + ")"), std::string::npos) << w;
    EXPECT_EQ(w.find("json.exception"), std::string::npos) << w;
    EXPECT_EQ(w.find("last read"), std::string::npos) << w;
    EXPECT_EQ(w.find('\xf4'), std::string::npos) << w;
  }
}

TEST(CoreQuote, JsonTypeAndKeyErrorsInFestWords) {
  const auto doc = nlohmann::json::parse(R"({"n": "x"})");
  try {
    (void)doc.at("n").get<double>();
    FAIL();
  } catch (const nlohmann::json::exception& e) {
    EXPECT_EQ(fest::json_failure_words(e.what(), 0, ""), "expected a number, got a string");
  }
  try {
    (void)doc.at("levels");
    FAIL();
  } catch (const nlohmann::json::exception& e) {
    EXPECT_EQ(fest::json_failure_words(e.what(), 0, ""), "field 'levels' missing");
  }
}

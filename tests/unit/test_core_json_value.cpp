// json_value.hpp: integers (and words) from untrusted JSON are taken only when the target type holds
// them exactly; everything else is the JSON library's own out_of_range / type_error (which
// callers already put in their words), never a cast that is undefined or wraps.
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/json_value.hpp"

using fest::json_integer;
using nlohmann::json;

TEST(JsonInteger, ExactValuesPass) {
  EXPECT_EQ(json_integer<int>(json::parse("42")), 42);
  EXPECT_EQ(json_integer<int>(json::parse("-7")), -7);
  EXPECT_EQ(json_integer<int>(json::parse("3.0")), 3);  // a float with an integral value
  EXPECT_EQ(json_integer<int>(json::parse("2147483647")), std::numeric_limits<int>::max());
  EXPECT_EQ(json_integer<int>(json::parse("-2147483648")), std::numeric_limits<int>::min());
  EXPECT_EQ(json_integer<std::uint64_t>(json::parse("18446744073709551615")), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(json_integer<std::int64_t>(json::parse("-9223372036854775808")), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(json_integer<std::uint32_t>(json::parse("4294967295.0")), 4294967295u);
}

TEST(JsonInteger, WhatDoesNotFitIsTheLibrarysOutOfRange) {
  for (const char* text : {"1.25556e31", "2147483648", "-2147483649", "4294967297", "2.5", "-1e308", "1e308"})
    EXPECT_THROW(json_integer<int>(json::parse(text)), json::out_of_range) << text;
  EXPECT_THROW(json_integer<std::size_t>(json::parse("-1")), json::out_of_range);
  EXPECT_THROW(json_integer<std::size_t>(json::parse("1.8446744073709552e19")), json::out_of_range);  // 2^64
  EXPECT_THROW(json_integer<std::int64_t>(json::parse("9.223372036854775808e18")), json::out_of_range);  // 2^63
  EXPECT_THROW(json_integer<std::uint8_t>(json::parse("256")), json::out_of_range);
  try {
    json_integer<int>(json::parse("1e31"));
  } catch (const json::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("expected an integer from -2147483648 to 2147483647, got 1e+31"), std::string::npos)
        << e.what();
  }
}

TEST(JsonInteger, NotANumberIsTheLibrarysTypeError) {
  EXPECT_THROW(json_integer<int>(json::parse("\"12\"")), json::type_error);
  EXPECT_THROW(json_integer<int>(json::parse("null")), json::type_error);
  EXPECT_THROW(json_integer<int>(json::parse("true")), json::type_error);
}

TEST(JsonInteger, ArraysAndDefaults) {
  EXPECT_EQ(fest::json_integers<int>(json::parse("[1, 2.0, -3]")), (std::vector<int>{1, 2, -3}));
  EXPECT_THROW(fest::json_integers<int>(json::parse("[1, 1e31]")), json::out_of_range);
  EXPECT_THROW(fest::json_integers<int>(json::parse("{}")), json::type_error);
  const json o = json::parse(R"({"w": 640, "bad": 1e40})");
  EXPECT_EQ(fest::json_integer_or<int>(o, "w", 1920), 640);
  EXPECT_EQ(fest::json_integer_or<int>(o, "h", 1080), 1080);
  EXPECT_THROW(fest::json_integer_or<int>(o, "bad", 1), json::out_of_range);
}

TEST(JsonStringOr, WordsOnly) {
  const json o = json::parse(R"({"units": "cm", "n": 5})");
  EXPECT_EQ(fest::json_string_or(o, "units", "mm"), "cm");
  EXPECT_EQ(fest::json_string_or(o, "source", ""), "");
  EXPECT_THROW(fest::json_string_or(o, "n", ""), json::type_error);
}

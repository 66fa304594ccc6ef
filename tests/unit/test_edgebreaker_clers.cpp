// The CLERS string form (lib/edgebreaker/clers.cpp).
#include <gtest/gtest.h>

#include "edgebreaker/clers.hpp"
#include "expect_error.hpp"

using namespace fest::edgebreaker;

TEST(EdgebreakerClers, LettersRoundTrip) {
  const Clers all{Symbol::C, Symbol::L, Symbol::E, Symbol::R, Symbol::S};
  EXPECT_EQ(to_string(all), "CLERS");
  EXPECT_EQ(parse_clers("CLERS"), all);
  EXPECT_EQ(to_string(parse_clers("CCCRCCCRRRCSREE")), "CCCRCCCRRRCSREE");
  EXPECT_TRUE(parse_clers("").empty());
}

TEST(EdgebreakerClers, RejectsOtherCharactersNamingThePosition) {
  fest::test::expect_bad_input([] { parse_clers("CCX"); }, "'X' at position 2");
  fest::test::expect_bad_input([] { parse_clers("cre"); }, "'c' at position 0");
  fest::test::expect_bad_input([] { parse_clers(std::string("CR\nE", 4)); }, "byte 0x0a at position 2");
}

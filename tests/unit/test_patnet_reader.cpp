// The PaT-Lisp reader: comments, quotes, #', strings, numbers, positions, errors.

#include <gtest/gtest.h>

#include "patnet/reader.hpp"

using namespace fest::patnet;

TEST(PatnetReader, AtomsListsAndQuotes) {
  const auto v = read_all("; comment\n(Foo :Bar 12 -3 2.5 1e3 \"a\\\"b\\\\c\" 'x #'car 1+)", 0);
  ASSERT_EQ(v.size(), 1u);
  const Datum& l = v[0];
  ASSERT_EQ(l.items.size(), 10u);
  EXPECT_EQ(l.items[0].text, "FOO");
  EXPECT_EQ(l.items[1].text, ":BAR");
  EXPECT_EQ(l.items[2].kind, Datum::Kind::integer);
  EXPECT_EQ(l.items[2].i, 12);
  EXPECT_EQ(l.items[3].i, -3);
  EXPECT_EQ(l.items[4].kind, Datum::Kind::real);
  EXPECT_DOUBLE_EQ(l.items[4].d, 2.5);
  EXPECT_DOUBLE_EQ(l.items[5].d, 1000.0);
  EXPECT_EQ(l.items[6].kind, Datum::Kind::string);
  EXPECT_EQ(l.items[6].text, "a\"b\\c");
  EXPECT_EQ(l.items[7].items[0].text, "QUOTE");
  EXPECT_EQ(l.items[7].items[1].text, "X");
  EXPECT_EQ(l.items[8].items[0].text, "FUNCTION");
  EXPECT_EQ(l.items[9].kind, Datum::Kind::symbol);  // 1+ is a function name
  EXPECT_EQ(l.items[9].text, "1+");
  EXPECT_EQ(l.pos.line, 2);
  EXPECT_EQ(l.pos.col, 1);
  EXPECT_EQ(l.items[2].pos.col, 11);
}

TEST(PatnetReader, ErrorsCarryPositions) {
  try {
    read_all("(a\n  (b c)", 0);
    FAIL();
  } catch (const ReadError& e) {
    EXPECT_NE(e.message.find("unbalanced"), std::string::npos);
    EXPECT_EQ(e.pos.line, 1);
    EXPECT_EQ(e.pos.col, 1);
  }
  EXPECT_THROW(read_all(")", 0), ReadError);
  EXPECT_THROW(read_all("\"abc", 0), ReadError);
  EXPECT_THROW(read_all("'", 0), ReadError);
  EXPECT_THROW(read_all("#x", 0), ReadError);
  EXPECT_THROW(read_all(std::string(5000, '('), 0), ReadError);  // nesting limit, not a stack overflow
}

// CSV/TSV tables: parsing rules (quoted names, comments, CRLF, nan/inf/empty cells),
// round trips, describe_table, and malformed input naming line and column.
#include <cmath>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/table/table_io.hpp"
#include "expect_error.hpp"
#include "testdata.hpp"

using fest::Table;
using fest::formats::Format;
using fest::formats::read_table;
using fest::formats::write_table;

namespace {

using fest::test::expect_bad_input;

Table csv(const std::string& text) { return read_table(text, Format::csv); }

}  // namespace

TEST(TableCsv, HeaderAndNumbers) {
  const Table t = csv("x,y,z\n1,2.5,-3e2\n4,5,6\n");
  EXPECT_EQ(t.names, (std::vector<std::string>{"x", "y", "z"}));
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.columns[0], (std::vector<double>{1, 4}));
  EXPECT_EQ(t.columns[1], (std::vector<double>{2.5, 5}));
  EXPECT_EQ(t.columns[2], (std::vector<double>{-300, 6}));
}

TEST(TableCsv, QuotedNamesCommentsCrlfAndBom) {
  const Table t = csv("\xEF\xBB\xBF# produced by a test\r\n# second comment\r\n\"a, b\",\"say \"\"hi\"\"\", plain \r\n1,2,3\r\n");
  EXPECT_EQ(t.names, (std::vector<std::string>{"a, b", "say \"hi\"", "plain"}));
  EXPECT_EQ(t.columns[2], (std::vector<double>{3}));
}

TEST(TableCsv, SpecialCells) {
  const Table t = csv("a,b,c,d\nnan,inf,-inf,\n+1,NaN,1e400,\"7\"\n");
  EXPECT_TRUE(std::isnan(t.columns[0][0]));
  EXPECT_EQ(t.columns[1][0], std::numeric_limits<double>::infinity());
  EXPECT_EQ(t.columns[2][0], -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(t.columns[3][0]));  // an empty cell is a missing value
  EXPECT_EQ(t.columns[0][1], 1.0);
  EXPECT_TRUE(std::isnan(t.columns[1][1]));
  EXPECT_EQ(t.columns[2][1], std::numeric_limits<double>::infinity());  // overflow
  EXPECT_EQ(t.columns[3][1], 7.0);
}

TEST(TableCsv, HeaderOnlyAndNoTrailingNewline) {
  EXPECT_EQ(csv("a,b\n").rows(), 0u);
  EXPECT_EQ(csv("a,b\n1,2").rows(), 1u);
  EXPECT_EQ(csv("a,b\n1,2\n\n\n").rows(), 1u);  // blank lines carry no rows
}

TEST(TableTsv, TabsAndSpacesInNames) {
  const Table t = read_table("first name\tsecond\n1\t2\n\t5\n", Format::tsv);
  EXPECT_EQ(t.names, (std::vector<std::string>{"first name", "second"}));
  EXPECT_TRUE(std::isnan(t.columns[0][1]));
  EXPECT_EQ(t.columns[1][1], 5.0);
}

TEST(TableCsv, RoundTripIsExactForEveryDouble) {
  Table t;
  t.add_column("plain", {0.1, 1.0 / 3.0, -2.5e-300, 1e300, 123456789012345678.0});
  t.add_column("needs, quotes", {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity(), -0.0, 5e-324});
  t.add_column("quote\"inside", {1, 2, 3, 4, 5});
  for (Format f : {Format::csv, Format::tsv}) {
    const Table back = read_table(write_table(t, f), f);
    ASSERT_EQ(back.names, t.names);
    for (std::size_t c = 0; c < t.cols(); ++c)
      for (std::size_t r = 0; r < t.rows(); ++r) {
        const double a = t.columns[c][r], b = back.columns[c][r];
        if (std::isnan(a)) {
          EXPECT_TRUE(std::isnan(b));
        } else {
          EXPECT_EQ(std::signbit(a), std::signbit(b));
          EXPECT_EQ(a, b) << c << "," << r;
        }
      }
  }
}

TEST(TableCsv, WriterUsesShortestForm) {
  Table t;
  t.add_column("v", {0.1, 2.0, 1e21});
  EXPECT_EQ(write_table(t, Format::csv), "v\n0.1\n2\n1e+21\n");
}

TEST(TableCsv, DescribeTable) {
  const nlohmann::json d = fest::formats::describe_table(csv("a,b\n3,nan\n-1,\n2,\n"));
  EXPECT_EQ(d["rows"], 3);
  ASSERT_EQ(d["columns"].size(), 2u);
  EXPECT_EQ(d["columns"][0]["name"], "a");
  EXPECT_EQ(d["columns"][0]["min"], -1.0);
  EXPECT_EQ(d["columns"][0]["max"], 3.0);
  EXPECT_TRUE(d["columns"][1]["min"].is_null());  // all missing
}

// ---- malformed input ----

TEST(TableCsvMalformed, EmptyOrCommentsOnly) {
  expect_bad_input([] { csv(""); }, "header");
  expect_bad_input([] { csv("# only a comment\n\n"); }, "header");
}

TEST(TableCsvMalformed, WrongCellCountNamesTheLine) {
  expect_bad_input([] { csv("a,b\n1,2\n1,2,3\n"); }, "line 3: 3 cells");
  expect_bad_input([] { csv("# c\na,b\n1\n"); }, "line 3: 1 cells");
}

TEST(TableCsvMalformed, NonNumericCellNamesLineAndColumn) {
  expect_bad_input([] { csv("a,b\n1,2\n3,abc\n"); }, "line 3, column 2 ('b'): 'abc'");
  expect_bad_input([] { csv("a,b\n1,2x\n"); }, "column 2");
  expect_bad_input([] { csv("a,b\n1,0x10\n"); }, "column 2");
  expect_bad_input([] { read_table("a\tb\n1\t2,5\n", Format::tsv); }, "TSV line 2, column 2");
}

TEST(TableCsvMalformed, QuotesAndDuplicates) {
  expect_bad_input([] { csv("\"open,b\n1,2\n"); }, "not closed");
  expect_bad_input([] { csv("\"a\"x,b\n1,2\n"); }, "after the closing quote");
  expect_bad_input([] { csv("a,a\n1,2\n"); }, "repeats");
}

TEST(TableCsvMalformed, NotATableFormat) {
  EXPECT_THROW(read_table("a\n1\n", Format::json), fest::Error);
  Table broken;
  broken.names = {"a", "b"};
  broken.columns = {{1, 2}, {3}};
  EXPECT_THROW(write_table(broken, Format::csv), fest::Error);
}

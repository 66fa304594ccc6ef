// lib/core/text_position.hpp and text_lines.hpp: the positions and lines the text readers
// (segbrain's rules, PaT-Lisp, JSON Lines inputs) report.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/text_lines.hpp"
#include "core/text_position.hpp"

namespace {

TEST(CoreTextReading, PositionCountsLinesAndColumnsFromOne) {
  fest::TextPosition p;
  for (char c : std::string("ab\ncd")) p.advance(c);
  EXPECT_EQ(p.line, 2);
  EXPECT_EQ(p.col, 3);
}

TEST(CoreTextReading, NonblankLinesKeepTheirNumbers) {
  std::vector<std::pair<int, std::string>> got;
  fest::for_each_nonblank_line("a\n\n \t\r\nb\r\nc", [&](int line, const std::string& text) { got.emplace_back(line, text); });
  const std::vector<std::pair<int, std::string>> want{{1, "a"}, {4, "b\r"}, {5, "c"}};
  EXPECT_EQ(got, want);
  got.clear();
  fest::for_each_nonblank_line("", [&](int line, const std::string& text) { got.emplace_back(line, text); });
  EXPECT_TRUE(got.empty());
}

}  // namespace

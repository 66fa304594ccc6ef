// lib/cli/enum_option.hpp's word_option: a flag's word becomes the value it names as the
// flag is parsed; any other word is a usage error "FLAG: unknown 'word' (w1, w2)" (the
// wording decimate's and ffd's tests rely on), reported before the command runs.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/enum_option.hpp"
#include "cli/word_choice.hpp"

namespace {

enum class Side { left, right };

// Parses `args` (after the tool name) into an app with --side; the fest::Error's text, or "".
std::string side_error(std::vector<std::string> args, Side& side) {
  CLI::App app{"test", "tool"};
  fest::cli::word_option(app, "--side", side, {{"left", Side::left}, {"right", Side::right}}, "left or right");
  std::vector<char*> argv{const_cast<char*>("tool")};
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    return e.what();
  }
  return {};
}

TEST(CliWordOption, TheWordNamesTheValue) {
  Side side = Side::left;
  EXPECT_EQ(side_error({"--side", "right"}, side), "");
  EXPECT_EQ(side, Side::right);
  side = Side::right;
  EXPECT_EQ(side_error({}, side), "");
  EXPECT_EQ(side, Side::right);  // absent: the default stays
}

TEST(CliWordOption, AnOtherWordIsAUsageErrorListingTheWords) {
  Side side = Side::left;
  EXPECT_EQ(side_error({"--side", "up"}, side), "--side: unknown 'up' (left, right)");
  EXPECT_EQ(side, Side::left);
}

TEST(CliWordChoice, TheNounIsNamedWhenGiven) {
  const std::vector<std::pair<std::string, int>> words{{"one", 1}, {"two", 2}};
  EXPECT_EQ(fest::cli::word_choice(std::string("two"), words, "--n", "count"), 2);
  try {
    fest::cli::word_choice(std::string("six"), words, "--n", "count");
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_STREQ(e.what(), "--n: unknown count 'six' (one, two)");
  }
}

}  // namespace

// lib/cli/cli.hpp's --threads (add_threads) and run(): the count is checked as it is parsed,
// worded with the flag the same for every tool, and reported like any other usage error.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli.hpp"
#include "cli/word_choice.hpp"

namespace {

// Parses `args` (after the tool name) into an app with --threads; the fest::Error thrown
// by the check, or none.
std::string threads_error(std::vector<std::string> args, int* threads = nullptr) {
  CLI::App app{"test", "tool"};
  int n = -99;
  fest::cli::add_threads(app, n);
  std::vector<char*> argv{const_cast<char*>("tool")};
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    return e.what();
  }
  if (threads) *threads = n;
  return {};
}

TEST(CliThreads, CountsAreCheckedWithTheFlagsWords) {
  int n = -1;
  EXPECT_EQ(threads_error({}, &n), "");
  EXPECT_EQ(n, 0);  // the default: all cores
  EXPECT_EQ(threads_error({"--threads", "3"}, &n), "");
  EXPECT_EQ(n, 3);
  EXPECT_EQ(threads_error({"--threads", "-2"}), "--threads must be 0 (all cores) or positive, not -2");
  EXPECT_EQ(threads_error({"--threads", "5000"}), "--threads 5000 is not a plausible thread count");
  // Not a number: CLI11's own conversion error, not ours.
  EXPECT_THROW(threads_error({"--threads", "two"}), CLI::ParseError);
}

TEST(CliThreads, RunReportsACheckErrorAsAUsageError) {
  CLI::App app{"test", "tool"};
  int n = 0;
  fest::cli::add_threads(app, n);
  std::vector<std::string> args{"tool", "--threads", "-1"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  bool ran = false;
  const int status = fest::cli::run(app, static_cast<int>(argv.size()), argv.data(), [&] {
    ran = true;
    return 0;
  });
  EXPECT_EQ(status, static_cast<int>(fest::Status::usage));
  EXPECT_FALSE(ran);
}

TEST(CliWordChoice, NamesTheFlagAndTheWords) {
  EXPECT_EQ(fest::cli::word_choice<int>("b", {{"a", 1}, {"b", 2}}, "--x", "thing"), 2);
  try {
    fest::cli::word_choice<int>("c", {{"a", 1}, {"b", 2}}, "--x", "thing");
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    EXPECT_EQ(std::string(e.what()), "--x: unknown thing 'c' (a, b)");
  }
}

}  // namespace

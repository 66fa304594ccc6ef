// lib/cli/number_range.hpp: ranges worded in plain numbers, and check_numbers' rule that a
// floating-point flag refuses NaN and infinities unless it is marked to take them.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli.hpp"

namespace {

struct Flags {
  double plain = 0, tol = 0.5, max_error = 1;
  std::optional<double> nodata;
  std::vector<double> list;
  int count = 1;
  double sub_value = 0;
};

// Parses `args` as cli::run does (parse, then check_numbers); the message of the usage
// error, or "" when the flags are accepted.
std::string parse_error(std::vector<std::string> args, Flags& f) {
  CLI::App app{"test", "tool"};
  app.add_option("--plain", f.plain);
  app.add_option("--tol", f.tol)->check(fest::cli::range(1e-15, 1.0));
  app.add_option("--max-error", f.max_error)->check(fest::cli::range(0.0, std::numeric_limits<double>::infinity()));
  app.add_option("--nodata", f.nodata)->check(fest::cli::accepts_nan);
  app.add_option("--list", f.list)->delimiter(',');
  app.add_option("--count", f.count)->check(fest::cli::range(1, 1000000));
  app.add_subcommand("sub", "a subcommand")->add_option("--value", f.sub_value)->check(fest::cli::positive);
  std::vector<char*> argv{const_cast<char*>("tool")};
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    fest::cli::check_numbers(app);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return {};
}

std::string error_of(std::vector<std::string> args) {
  Flags f;
  return parse_error(std::move(args), f);
}

TEST(CliNumberRange, RangeNamesItsBoundsInPlainNumbers) {
  EXPECT_EQ(error_of({"--tol", "nan"}), "--tol: must be in [1e-15, 1], not nan");
  EXPECT_EQ(error_of({"--tol", "-1"}), "--tol: must be in [1e-15, 1], not -1");
  EXPECT_EQ(error_of({"--tol", "inf"}), "--tol: must be in [1e-15, 1], not inf");
  EXPECT_EQ(error_of({"--count", "1e308"}), "--count: must be in [1, 1000000], not 1e308");
  EXPECT_EQ(error_of({"--tol", "0.25"}), "");
}

TEST(CliNumberRange, EveryFloatingPointFlagRefusesNanAndInfinity) {
  EXPECT_EQ(error_of({"--plain", "nan"}), "--plain: must be a finite number, not nan");
  EXPECT_EQ(error_of({"--plain", "-inf"}), "--plain: must be a finite number, not -inf");
  EXPECT_EQ(error_of({"--list", "1,inf"}), "--list: must be a finite number, not inf");
  EXPECT_EQ(error_of({"sub", "--value", "nan"}), "--value: must be a positive number, not nan");
  EXPECT_EQ(error_of({"--plain", "1e308"}), "");
}

TEST(CliNumberRange, MarkedFlagsTakeWhatTheirMarkSays) {
  Flags f;
  EXPECT_EQ(parse_error({"--max-error", "inf"}, f), "");
  EXPECT_TRUE(f.max_error > 1e308);
  EXPECT_EQ(error_of({"--max-error", "nan"}), "--max-error: must be in [0, inf], not nan");
  EXPECT_EQ(parse_error({"--nodata", "nan"}, f), "");
  EXPECT_TRUE(f.nodata && *f.nodata != *f.nodata);
  EXPECT_EQ(error_of({"--nodata", "inf"}), "--nodata: must be a finite number, not inf");
}

TEST(CliNumberRange, LongValuesAreQuotedShortened) {
  const std::string digits(400, '9');
  const std::string e = error_of({"--tol", digits});
  EXPECT_LT(e.size(), 80u) << e;
  EXPECT_NE(e.find("..."), std::string::npos) << e;
}

}  // namespace

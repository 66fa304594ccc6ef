// The flag values main.cpp parses before a command runs (option_values.cpp): seed
// points, seed lines and the parallel sweep become numbers once, and the usage errors
// name the flag and quote the text as they did when the commands parsed them.

#include <gtest/gtest.h>

#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "expect_error.hpp"

namespace {

using namespace fest::lemtrace_tool;

using fest::test::usage_message;

TEST(LemtraceToolOptions, SeedPoint) {
  const auto p = parse_seed_point("0.5,-1,2e-3");
  EXPECT_EQ(p[0], 0.5);
  EXPECT_EQ(p[1], -1.0);
  EXPECT_EQ(p[2], 2e-3);
  EXPECT_EQ(usage_message([] { parse_seed_point("1,2"); }), "--seed-point '1,2': expected 3 numbers separated by commas");
  EXPECT_EQ(usage_message([] { parse_seed_point("0,a,0"); }), "--seed-point '0,a,0': 'a' is not a number");
  EXPECT_EQ(usage_message([] { parse_seed_point("0,inf,0"); }), "--seed-point '0,inf,0': 'inf' is not a number");
}

TEST(LemtraceToolOptions, SeedLine) {
  const SeedLine l = parse_seed_line("0,0,0:1,2,3:5");
  EXPECT_EQ(l.from[0], 0.0);
  EXPECT_EQ(l.to[2], 3.0);
  EXPECT_EQ(l.n, 5);
  EXPECT_EQ(usage_message([] { parse_seed_line("0,0,0:1,1"); }), "--seed-line '0,0,0:1,1': expected x0,y0,z0:x1,y1,z1:n");
  EXPECT_EQ(usage_message([] { parse_seed_line("0,0,0:1,1,1:0"); }), "--seed-line '0,0,0:1,1,1:0': n must be a positive integer");
  EXPECT_EQ(usage_message([] { parse_seed_line("0,0,0:1,1,1:2.5"); }), "--seed-line '0,0,0:1,1,1:2.5': n must be a positive integer");
}

TEST(LemtraceToolOptions, ParallelSweep) {
  const ParallelSweep s = parse_parallel_sweep("1e-7:1e-1");
  EXPECT_EQ(s.from, 1e-7);
  EXPECT_EQ(s.to, 1e-1);
  EXPECT_EQ(usage_message([] { parse_parallel_sweep("1e-3"); }), "--sweep-parallel '1e-3': expected FROM:TO, e.g. 1e-7:1e-1");
  EXPECT_EQ(usage_message([] { parse_parallel_sweep("1e-1:1e-3"); }), "--sweep-parallel '1e-1:1e-3': need 0 < FROM <= TO");
}

TEST(LemtraceToolOptions, LineFormatNames) {
  EXPECT_STREQ(line_format_name(LineFormat::csv), "csv");
  EXPECT_STREQ(line_format_name(LineFormat::json), "json");
  EXPECT_STREQ(line_format_name(LineFormat::unset), "");
}

}  // namespace

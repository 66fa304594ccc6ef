// lib/cli/number_list.hpp: comma lists parsed once into typed options, with usage errors
// that name the flag.
#include <functional>

#include <gtest/gtest.h>

#include "cli/number_list.hpp"

namespace {

fest::Status status_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    return e.status();
  }
  return fest::Status::ok;
}

TEST(CliNumberList, ParsesCountsAndSeparators) {
  EXPECT_EQ(fest::cli::number_list("852,567", 2, 2, "--size"), (std::vector<double>{852, 567}));
  EXPECT_EQ(fest::cli::number_list("-1.5e2", 1, 0, "--x"), (std::vector<double>{-150}));
  EXPECT_EQ(fest::cli::number_list("1;2;3", 3, 3, "--p", ';'), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(fest::cli::integer_list("0,30,60", 1, 0, "--angles", 0, 359), (std::vector<long long>{0, 30, 60}));
}

TEST(CliNumberList, RefusesWithTheFlagName) {
  for (const char* bad : {"", "1,", ",1", "1,x", "nan", "inf", "1 2"})
    EXPECT_EQ(status_of([&] { fest::cli::number_list(bad, 1, 0, "--size"); }), fest::Status::usage) << bad;
  EXPECT_EQ(status_of([] { fest::cli::number_list("1,2,3", 2, 2, "--size"); }), fest::Status::usage);
  EXPECT_EQ(status_of([] { fest::cli::integer_list("1.5", 1, 1, "--n", 0, 9); }), fest::Status::usage);
  EXPECT_EQ(status_of([] { fest::cli::integer_list("10", 1, 1, "--n", 0, 9); }), fest::Status::usage);
  try {
    fest::cli::number_list("1,2,3", 2, 2, "--size");
  } catch (const fest::Error& e) {
    EXPECT_NE(std::string(e.what()).find("--size takes 2 numbers, got 3"), std::string::npos) << e.what();
  }
}

}  // namespace

// fest::ProgressCounter: counts from every thread of a parallel loop, reports only on the
// thread that made it, never more than the total, and ends at (total, total); a stage that
// is one part of a longer one reports in the longer one's steps. Progress::callback draws
// what a stage reports.

#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel_for.hpp"
#include "core/progress.hpp"
#include "core/progress_callback.hpp"

namespace {

TEST(ProgressCounter, ReportsOnlyOnTheOwningThreadAndEndsAtTheTotal) {
  const std::thread::id owner = std::this_thread::get_id();
  std::vector<std::pair<std::uint64_t, std::uint64_t>> calls;
  bool foreign = false;
  fest::ProgressFn fn = [&](std::uint64_t done, std::uint64_t total) {
    if (std::this_thread::get_id() != owner) foreign = true;
    calls.emplace_back(done, total);  // unsynchronised on purpose: only the owner may get here
  };
  fest::ProgressCounter counter(fn, 1000);
  fest::parallel_for(1000, 4, [&](std::size_t) { counter.step(); });
  EXPECT_EQ(counter.done(), 1000u);
  counter.finish();
  EXPECT_FALSE(foreign);
  ASSERT_FALSE(calls.empty());
  for (std::size_t i = 0; i < calls.size(); ++i) {
    EXPECT_LE(calls[i].first, 1000u);
    EXPECT_EQ(calls[i].second, 1000u);
    if (i > 0) {
      EXPECT_GE(calls[i].first, calls[i - 1].first);  // the count never goes back
    }
  }
  EXPECT_EQ(calls.back(), std::make_pair(std::uint64_t{1000}, std::uint64_t{1000}));
}

TEST(ProgressCounter, OnePartOfALongerStage) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> calls;
  fest::ProgressFn fn = [&](std::uint64_t done, std::uint64_t total) { calls.emplace_back(done, total); };
  fest::ProgressCounter second(fn, 5, 10, 20);  // steps 10..15 of 20
  second.step(2);
  second.finish();
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0], std::make_pair(std::uint64_t{12}, std::uint64_t{20}));
  EXPECT_EQ(calls[1], std::make_pair(std::uint64_t{15}, std::uint64_t{20}));
}

TEST(ProgressCounter, EmptyFunctionIsSilent) {
  fest::ProgressCounter counter({}, 3);
  counter.step();
  counter.finish();
  EXPECT_EQ(counter.done(), 3u);
}

TEST(Progress, CallbackDrawsTheReportedFraction) {
  std::FILE* f = std::tmpfile();
  {
    fest::Progress bar("stage", 0, true, f);
    fest::ProgressFn fn = bar.callback();
    fn(1, 4);  // the first draw is never held back
    bar.finish();
  }
  std::rewind(f);
  char buf[512] = {};
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  const std::string text(buf, n);
  EXPECT_NE(text.find(" 25%"), std::string::npos) << text;
  EXPECT_NE(text.find("100%"), std::string::npos) << text;
}

TEST(ProgressPart, OneStageOfSeveralInThousandths) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> calls;
  fest::ProgressFn fn = [&](std::uint64_t done, std::uint64_t total) { calls.emplace_back(done, total); };
  fest::ProgressFn second = fest::progress_part(fn, 0.25, 0.75);  // the middle half of the bar
  second(0, 10);
  second(5, 10);
  second(12, 10);  // more than the total: the part's end, never beyond
  second(3, 0);    // an unknown total: the part's start
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_EQ(calls[0], std::make_pair(std::uint64_t{250}, std::uint64_t{1000}));
  EXPECT_EQ(calls[1], std::make_pair(std::uint64_t{500}, std::uint64_t{1000}));
  EXPECT_EQ(calls[2], std::make_pair(std::uint64_t{750}, std::uint64_t{1000}));
  EXPECT_EQ(calls[3], std::make_pair(std::uint64_t{250}, std::uint64_t{1000}));
  EXPECT_FALSE(fest::progress_part({}, 0.0, 1.0)) << "nobody listening stays nobody listening";
}

// README "Conventions": -q hides the automatic bar, an explicit --progress draws it anyway.
// (Whether standard error is a terminal decides the rest; neither case below depends on it.)
TEST(ProgressWanted, ExplicitProgressWinsOverQuiet) {
  fest::set_progress_quiet(true);
  EXPECT_TRUE(fest::progress_wanted(true));
  EXPECT_FALSE(fest::progress_wanted(false)) << "-q: no automatic bar, terminal or not";
  fest::set_progress_quiet(false);
  EXPECT_TRUE(fest::progress_wanted(true));
}

}  // namespace

// fest::parallel_for when the system refuses threads (issue 31): every job still runs once,
// on the threads that did start and the calling one, and a job's failure is still rethrown
// after all of them have joined -- never std::terminate from an unjoined std::thread.

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel_for.hpp"

namespace {

// Sets the hook for one test and clears it afterwards, also when the test fails.
struct ThreadLimit {
  explicit ThreadLimit(int n) { fest::detail::thread_start_limit_for_tests = n; }
  ~ThreadLimit() { fest::detail::thread_start_limit_for_tests = -1; }
};

std::vector<int> run_counts(std::size_t count, int threads) {
  std::vector<std::atomic<int>> runs(count);
  fest::parallel_for(count, threads, [&](std::size_t i) { runs[i].fetch_add(1); });
  std::vector<int> out;
  for (auto& r : runs) out.push_back(r.load());
  return out;
}

}  // namespace

TEST(ParallelFor, EveryJobOnceWithAllThreads) {
  EXPECT_EQ(run_counts(1000, 8), std::vector<int>(1000, 1));
}

TEST(ParallelFor, NoThreadStartsEveryJobRunsOnTheCaller) {
  ThreadLimit limit(0);
  EXPECT_EQ(run_counts(1000, 8), std::vector<int>(1000, 1));
}

TEST(ParallelFor, SomeThreadsStartThenTheSystemRefusesEveryJobRunsOnce) {
  for (int started : {1, 2, 3}) {
    ThreadLimit limit(started);
    EXPECT_EQ(run_counts(1000, 8), std::vector<int>(1000, 1)) << started << " threads started";
  }
}

TEST(ParallelFor, AJobFailureIsRethrownOnceAfterARefusedThread) {
  ThreadLimit limit(2);
  std::atomic<int> ran{0};
  EXPECT_THROW(fest::parallel_for(1000, 8,
                                  [&](std::size_t i) {
                                    ran.fetch_add(1);
                                    if (i == 10) throw std::runtime_error("job 10");
                                  }),
               std::runtime_error);
  EXPECT_GE(ran.load(), 11);
}

TEST(ParallelFor, BandsCoverTheRangeWhenThreadsAreRefused) {
  ThreadLimit limit(1);
  std::vector<std::atomic<int>> rows(97);
  fest::parallel_bands(97, 6, [&](int begin, int end) {
    for (int r = begin; r < end; ++r) rows[static_cast<std::size_t>(r)].fetch_add(1);
  });
  for (auto& r : rows) EXPECT_EQ(r.load(), 1);
}

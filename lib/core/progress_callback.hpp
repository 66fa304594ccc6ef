#pragma once
// How a long stage in lib/ says how far it has come without printing anything: it calls
// a ProgressFn with (steps done, steps in all), and the tool turns that into a bar
// (core/progress.hpp, Progress::callback). An empty ProgressFn means nobody listens.
//
// A parallel loop counts its finished jobs in a ProgressCounter: any thread may count,
// only the thread that made the counter calls the ProgressFn, so the bar is drawn from one
// thread and the callback needs no lock. parallel_for's calling thread takes jobs too, so
// the count reaches the bar while the loop runs.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

#include "core/progress_fn.hpp"

namespace fest {

class ProgressCounter {
 public:
  ProgressCounter(const ProgressFn& fn, std::uint64_t total, std::uint64_t offset = 0, std::uint64_t all = 0)
      : fn_(fn), total_(total), offset_(offset), all_(all > 0 ? all : total), owner_(std::this_thread::get_id()) {}

  // `n` more steps finished; safe from any thread.
  void step(std::uint64_t n = 1) {
    const std::uint64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
    if (fn_ && std::this_thread::get_id() == owner_) fn_(offset_ + done, all_);
  }

  // Every step finished (call on the owning thread once the loop has joined).
  void finish() {
    done_.store(total_, std::memory_order_relaxed);
    if (fn_) fn_(offset_ + total_, all_);
  }

  std::uint64_t done() const { return done_.load(std::memory_order_relaxed); }

 private:
  ProgressFn fn_;
  std::uint64_t total_;
  std::uint64_t offset_;  // a stage that is one part of a longer one: its steps start here ...
  std::uint64_t all_;     // ... of this many in all
  std::thread::id owner_;
  std::atomic<std::uint64_t> done_{0};
};

// One stage of several that share one bar: the stage reports its own (done, total), the bar
// sees the whole in thousandths, this stage covering [begin, end) of it (fractions). An
// empty `fn` gives an empty ProgressFn.
inline ProgressFn progress_part(const ProgressFn& fn, double begin, double end) {
  if (!fn) return {};
  return [fn, begin, end](std::uint64_t done, std::uint64_t total) {
    const double f = total > 0 ? static_cast<double>(std::min(done, total)) / static_cast<double>(total) : 0.0;
    fn(static_cast<std::uint64_t>(1000.0 * (begin + (end - begin) * f) + 0.5), 1000);
  };
}

}  // namespace fest

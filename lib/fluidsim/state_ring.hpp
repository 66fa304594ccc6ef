#pragma once
// The producer/consumer buffer of docs/fluidsim.md §5 (seed Fig. 6.1): the solver
// thread writes complete states into a ring of 3 slots while the frame writer reads the
// two consecutive states it interpolates between; only the hand-over is locked.

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>

#include "fluidsim/simulator.hpp"

namespace fest::fluidsim {

struct RingEntry {
  long level = 0;
  State state;
  StepStats stats;  // of the step that produced it (zero for level 0)
};

class StateRing {
 public:
  explicit StateRing(std::size_t slots = 3) : slots_(slots) {}

  // Solver: waits for a free slot, then publishes the next level.
  void push(RingEntry entry) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return entries_.size() < slots_ || cancelled_; });
    if (cancelled_) return;
    entries_.push_back(std::move(entry));
    changed_.notify_all();
  }
  // Solver: no more levels; `error` (if any) is rethrown to a reader that waits for one.
  void finish(std::exception_ptr error = nullptr) {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    error_ = error;
    changed_.notify_all();
  }
  // Writer: the entry of `level`, waiting until the solver has published it. Throws the
  // solver's error when it stopped before that level.
  const RingEntry& get(long level) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      for (const RingEntry& e : entries_)
        if (e.level == level) return e;
      if (finished_) {
        if (error_) std::rethrow_exception(error_);
        throw std::logic_error("state ring: level never produced");
      }
      changed_.wait(lock);
    }
  }
  // Writer: levels below `level` are no longer needed; their slots are reused.
  void release_below(long level) {
    std::lock_guard<std::mutex> lock(mutex_);
    while (!entries_.empty() && entries_.front().level < level) entries_.pop_front();
    changed_.notify_all();
  }
  // Writer gave up (its own error): unblocks the solver.
  void cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
    changed_.notify_all();
  }
  bool cancelled() {
    std::lock_guard<std::mutex> lock(mutex_);
    return cancelled_;
  }

 private:
  std::size_t slots_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<RingEntry> entries_;  // consecutive levels, oldest first; entries never move
  bool finished_ = false, cancelled_ = false;
  std::exception_ptr error_;
};

}  // namespace fest::fluidsim

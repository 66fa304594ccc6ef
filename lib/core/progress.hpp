#pragma once
// A progress bar on standard error, shown only when standard error is a terminal or the
// user asked with --progress (README "Conventions": silent in pipelines otherwise).

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/progress_callback.hpp"

namespace fest {

// Whether a tool should draw progress: asked for explicitly (--progress), or standard
// error is a terminal and -q was not given. One rule for every tool (README
// "Conventions"): -q hides the automatic bar; an explicit --progress draws it even with -q
// (as wget -q --show-progress: the bar and errors, nothing else).
bool progress_wanted(bool requested);

// -q/--quiet was given: set once by cli::run after parsing, before any stage starts.
void set_progress_quiet(bool quiet);

class Progress {
 public:
  // total == 0 means unknown: a counter is drawn instead of a bar.
  Progress(std::string label, std::uint64_t total, bool enabled, std::FILE* out = stderr);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t steps = 1);
  void set(std::uint64_t done);
  void set(std::uint64_t done, std::uint64_t total);  // the total as the stage reports it
  // What a stage in lib/ reports to (core/progress_callback.hpp): set(done, total). The
  // Progress must outlive the stage.
  ProgressFn callback() {
    return [this](std::uint64_t done, std::uint64_t total) { set(done, total); };
  }
  void finish();  // draws 100 % and ends the line; idempotent

  // The line that would be drawn for `done` of `total`; exposed for tests.
  static std::string render(const std::string& label, std::uint64_t done, std::uint64_t total,
                            int width = 30);

 private:
  void draw(bool force);

  std::string label_;
  std::uint64_t total_;
  std::uint64_t done_ = 0;
  bool enabled_;
  bool finished_ = false;
  std::FILE* out_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace fest

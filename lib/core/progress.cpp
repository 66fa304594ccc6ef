#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>

namespace fest {

namespace {
bool quiet_run = false;
}  // namespace

void set_progress_quiet(bool quiet) { quiet_run = quiet; }

bool progress_wanted(bool requested) { return requested || (!quiet_run && ::isatty(STDERR_FILENO) == 1); }

Progress::Progress(std::string label, std::uint64_t total, bool enabled, std::FILE* out)
    : label_(std::move(label)), total_(total), enabled_(enabled), out_(out) {}

Progress::~Progress() {
  if (enabled_ && !finished_ && done_ > 0) {
    // Leave the terminal on a fresh line if the work ended early (an exception).
    std::fputc('\n', out_);
  }
}

std::string Progress::render(const std::string& label, std::uint64_t done, std::uint64_t total,
                             int width) {
  if (total == 0) return fmt::format("{}: {}", label, done);
  done = std::min(done, total);
  const double frac = static_cast<double>(done) / static_cast<double>(total);
  const int filled = static_cast<int>(frac * width);
  return fmt::format("{}: [{}{}] {:3d}%", label, std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(width - filled), ' '),
                     static_cast<int>(frac * 100.0));
}

void Progress::draw(bool force) {
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  // Redrawing more than ~10 times a second costs time and flickers.
  if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  std::fprintf(out_, "\r%s", render(label_, done_, total_).c_str());
  std::fflush(out_);
}

void Progress::advance(std::uint64_t steps) {
  done_ += steps;
  draw(false);
}

void Progress::set(std::uint64_t done) {
  done_ = done;
  draw(false);
}

void Progress::set(std::uint64_t done, std::uint64_t total) {
  total_ = total;
  set(done);
}

void Progress::finish() {
  if (finished_) return;
  if (total_ > 0) done_ = total_;
  draw(true);
  if (enabled_) std::fputc('\n', out_);
  finished_ = true;
}

}  // namespace fest

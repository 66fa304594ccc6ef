#include "devices/gpio_stepper.hpp"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "capture/device_uri.hpp"
#include "capture/step_profile.hpp"
#include "core/error.hpp"
#include "devices/gpio_util.hpp"

namespace fest::devices {
namespace {

constexpr long kDirSetupNs = 5000;  // DIR stable before the first STEP edge (drivers: >= 200 ns .. 5 us)
constexpr long kPulseNs = 2000;     // STEP high time

std::uint32_t positive(const std::string& key, const std::string& v) {
  char* end = nullptr;
  const unsigned long n = std::strtoul(v.c_str(), &end, 10);
  if (v.empty() || end != v.c_str() + v.size() || n == 0 || n > 100000000UL)
    throw usage_error("gpio-stepper: {}={} is not a positive integer", key, v);
  return std::uint32_t(n);
}

timespec now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t;
}

timespec plus(timespec t, double seconds) {
  const long long ns = (long long)(t.tv_nsec) + (long long)std::llround(seconds * 1e9);
  t.tv_sec += time_t(ns / 1000000000LL);
  t.tv_nsec = long(ns % 1000000000LL);
  return t;
}

void sleep_until(const timespec& t) {
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr) == EINTR) {
  }
}

}  // namespace

GpioStepperConfig parse_gpio_stepper_uri(const std::string& uri) {
  if (uri.rfind("gpio-stepper:", 0) != 0) throw usage_error("not a gpio-stepper: URI: {}", uri);
  GpioStepperConfig c;
  for (const capture::DeviceOption& o : capture::split_device_options(uri.substr(13))) {
    const std::string& key = o.key;
    const std::string& value = o.value;
    const std::string& item = o.item;
    if (!o.has_value && key == "home_active_low") c.home_active_low = true;
    else if (!o.has_value && key == "en_active_high") c.en_active_high = true;
    else if (!o.has_value || value.empty())
      throw usage_error("gpio-stepper: '{}' is not key=value (in {})", item, uri);
    else if (key == "chip") c.chip = value;
    else if (key == "step") c.step = value;
    else if (key == "dir") c.dir = value;
    else if (key == "en") c.en = value;
    else if (key == "home") c.home = value;
    else if (key == "steps") c.steps_per_rev = positive(key, value);
    else if (key == "speed") c.max_speed = positive(key, value);
    else if (key == "accel") c.max_accel = positive(key, value);
    else
      throw usage_error("gpio-stepper: unknown key '{}' (chip, step, dir, en, home, steps, speed, accel, home_active_low, "
                        "en_active_high)",
                        key);
  }
  if (c.step.empty() || c.dir.empty()) throw usage_error("gpio-stepper needs step= and dir= lines: {}", uri);
  return c;
}

struct GpioStepper::Lines {
  gpiod_chip* chip = nullptr;
  gpiod_line *step = nullptr, *dir = nullptr, *en = nullptr, *home = nullptr;
  std::string step_where, dir_where;
  ~Lines() {
    for (gpiod_line* l : {step, dir, en, home})
      if (l) gpiod_line_release(l);
    if (chip) gpiod_chip_close(chip);
  }
};

GpioStepper::GpioStepper(const GpioStepperConfig& config) : config_(config), lines_(std::make_unique<Lines>()) {
  Lines& l = *lines_;
  l.chip = gpio::open_chip(config.chip);
  const auto line = [&](const std::string& name) { return gpio::find_line(l.chip, GpioLineRef{config.chip, name, false}); };
  gpiod_line* step = line(config.step);
  gpiod_line* dir = line(config.dir);
  if (step == dir) throw usage_error("gpio-stepper: step and dir are the same line");
  l.step_where = gpio::describe({config.chip, config.step, false}, step);
  l.dir_where = gpio::describe({config.chip, config.dir, false}, dir);
  gpio::request_output(step, "turntable STEP", false, false, l.step_where);
  l.step = step;
  gpio::request_output(dir, "turntable DIR", false, false, l.dir_where);
  l.dir = dir;
  dir_level_ = 0;
  if (!config.en.empty()) {
    gpiod_line* en = line(config.en);
    gpio::request_output(en, "turntable EN", !config.en_active_high, true, gpio::describe({config.chip, config.en, false}, en));
    l.en = en;
  }
  if (!config.home.empty()) {
    gpiod_line* home = line(config.home);
    const std::string where = gpio::describe({config.chip, config.home, false}, home);
    const int flags = config.home_active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
    errno = 0;
    if (gpiod_line_request_input_flags(home, "capture", flags) < 0) {
      const int err = errno;
      if (err == EBUSY)
        throw make_error(Status::device_error, "turntable HOME: {} is busy, held by '{}'", where, gpio::consumer_of(home));
      gpio::throw_errno(err, "turntable HOME: cannot request the line", where);
    }
    l.home = home;
  }
}

// The step train comes from this process: a move still running (turntable move
// --no-wait) is completed before the lines are released.
GpioStepper::~GpioStepper() {
  if (worker_.joinable()) worker_.join();
}

void GpioStepper::fail(const Error& e) {
  std::lock_guard<std::mutex> lock(mutex_);
  error_status_ = e.status();
  error_ = e.what();
  state_ = capture::MotionState::fault;
}

void GpioStepper::pulse(int direction) {
  const int level = direction > 0 ? 1 : 0;
  if (level != dir_level_) {
    errno = 0;
    if (gpiod_line_set_value(lines_->dir, level) < 0) gpio::throw_errno(errno, "turntable DIR", lines_->dir_where);
    dir_level_ = level;
    sleep_until(plus(now(), kDirSetupNs * 1e-9));
  }
  errno = 0;
  if (gpiod_line_set_value(lines_->step, 1) < 0) gpio::throw_errno(errno, "turntable STEP", lines_->step_where);
  sleep_until(plus(now(), kPulseNs * 1e-9));
  errno = 0;
  if (gpiod_line_set_value(lines_->step, 0) < 0) gpio::throw_errno(errno, "turntable STEP", lines_->step_where);
  position_ += direction;
}

void GpioStepper::make_realtime() {
  sched_param p{};
  p.sched_priority = 50;
  if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) != 0) realtime_ = false;
}

void GpioStepper::run_move(std::int32_t target, double speed) {
  make_realtime();
  try {
    const std::int64_t distance = std::int64_t(target) - position_.load();
    const int direction = distance >= 0 ? 1 : -1;
    const std::uint32_t n = std::uint32_t(std::llabs(distance));
    const std::vector<double> times = capture::trapezoid_step_times(n, speed, double(config_.max_accel));
    const timespec start = now();
    for (std::uint32_t k = 0; k < n; ++k) {
      if (stop_request_ == 2) break;
      if (stop_request_ == 1) {
        // Decelerate from the current speed: v^2 / 2a more steps, each interval longer.
        const double v = k > 0 ? 1.0 / std::max(times[k] - times[k - 1], 1e-6) : 0.0;
        const std::uint32_t tail = std::min<std::uint32_t>(n - k, std::uint32_t(std::ceil(v * v / (2.0 * config_.max_accel))));
        for (std::uint32_t j = 1; j <= tail; ++j) {
          const double vj = std::sqrt(std::max(v * v - 2.0 * config_.max_accel * j, double(config_.max_accel)));
          sleep_until(plus(now(), 1.0 / vj));
          pulse(direction);
        }
        break;
      }
      sleep_until(plus(start, times[k]));
      pulse(direction);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (stop_request_ != 0) target_ = position_;
    state_ = capture::MotionState::idle;
    ++seq_;
  } catch (const Error& e) {
    fail(e);
  }
}

void GpioStepper::run_home(bool clockwise, double speed) {
  make_realtime();
  try {
    const int direction = clockwise ? -1 : 1;
    const std::uint32_t limit = std::uint32_t(std::ceil(1.1 * config_.steps_per_rev));
    timespec next = now();
    for (std::uint32_t k = 0;; ++k) {
      errno = 0;
      const int active = gpiod_line_get_value(lines_->home);
      if (active < 0) gpio::throw_errno(errno, "turntable HOME", config_.home);
      if (active == 1) {
        std::lock_guard<std::mutex> lock(mutex_);
        position_ = 0;
        target_ = 0;
        homed_ = true;
        state_ = capture::MotionState::idle;
        ++seq_;
        return;
      }
      if (stop_request_ != 0) break;
      if (k == limit) {
        std::lock_guard<std::mutex> lock(mutex_);
        state_ = capture::MotionState::fault;
        fault_ = 2;  // home switch not found
        return;
      }
      next = plus(next, 1.0 / speed);
      sleep_until(next);
      pulse(direction);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    target_ = position_;
    state_ = capture::MotionState::idle;
  } catch (const Error& e) {
    fail(e);
  }
}

void GpioStepper::halt(bool immediate) {
  if (!worker_.joinable()) return;
  stop_request_ = immediate ? 2 : 1;
  worker_.join();
  stop_request_ = 0;
}

capture::TurntableInfo GpioStepper::info() {
  capture::TurntableInfo i;
  i.steps_per_rev = config_.steps_per_rev;
  i.max_speed = config_.max_speed;
  i.max_accel = config_.max_accel;
  i.has_home = lines_->home != nullptr;
  i.name = "gpio step/dir on " + config_.chip;
  return i;
}

capture::TurntableStatus GpioStepper::status() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (error_status_ != Status::ok) throw Error(error_status_, error_);
  capture::TurntableStatus s;
  s.position = position_;
  s.target = target_;
  s.state = state_;
  s.homed = homed_;
  s.fault = fault_;
  s.driver_enabled = enabled_;
  s.seq = seq_;
  return s;
}

void GpioStepper::move_abs(std::int32_t target, std::uint32_t speed) {
  halt(true);  // a new target replaces the running move (the step train restarts from rest)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_status_ != Status::ok) throw Error(error_status_, error_);
    if (state_ == capture::MotionState::fault)
      throw make_error(Status::device_error, "turntable in fault {} ({}): home it first", fault_, fault_ == 2 ? "home switch not found" : "fault");
    if (!enabled_) throw make_error(Status::device_error, "turntable driver is disabled ('turntable enable')");
    target_ = target;
    state_ = target == position_ ? capture::MotionState::idle : capture::MotionState::moving;
  }
  const double v = std::min<double>(speed ? speed : config_.max_speed, config_.max_speed);
  worker_ = std::thread([this, target, v] { run_move(target, v); });
}

void GpioStepper::home(bool clockwise, std::uint32_t speed) {
  if (!lines_->home) throw make_error(Status::device_error, "this turntable has no home switch (gpio-stepper: add home=LINE)");
  halt(true);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_status_ != Status::ok) throw Error(error_status_, error_);
    state_ = capture::MotionState::homing;
    fault_ = 0;
  }
  // Homing creeps: a quarter of the maximum speed unless told otherwise.
  const double v = std::min<double>(speed ? speed : std::max(1u, config_.max_speed / 4), config_.max_speed);
  worker_ = std::thread([this, clockwise, v] { run_home(clockwise, v); });
}

void GpioStepper::stop(bool immediate) { halt(immediate); }

void GpioStepper::wait_ms(unsigned ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

void GpioStepper::set_zero() {
  halt(true);
  std::lock_guard<std::mutex> lock(mutex_);
  position_ = 0;
  target_ = 0;
}

void GpioStepper::enable(bool on) {
  if (!lines_->en) throw make_error(Status::device_error, "this turntable has no driver enable line (gpio-stepper: add en=LINE)");
  if (!on) halt(true);
  std::lock_guard<std::mutex> lock(mutex_);
  errno = 0;
  if (gpiod_line_set_value(lines_->en, on ? 1 : 0) < 0) gpio::throw_errno(errno, "turntable EN", config_.en);
  enabled_ = on;
}

}  // namespace fest::devices

#pragma once
// A turntable on a step/dir stepper driver (A4988, DRV8825, TMC2208/2209) wired to GPIO
// lines, driven through libgpiod 1.6 (docs/turntable.md §3): the host generates the
// step train with a trapezoidal profile on a worker thread, so move_abs returns at once
// and status() reports progress like any Turntable.
//
//   gpio-stepper:chip=gpiochip0,step=17,dir=27[,en=22][,home=23][,steps=3200]
//                [,speed=2000][,accel=4000][,home_active_low][,en_active_high]
//
// Lines by offset or name. DIR high = positive steps = counter-clockwise. EN is active
// low (the drivers above) unless en_active_high. Timing: DIR settles >= 5 us before the
// first pulse, STEP stays high >= 2 us; deadlines on CLOCK_MONOTONIC with absolute
// sleeps. One ioctl per edge limits the rate to some 10-20 kHz; non-realtime kernels
// jitter, which is harmless for positioning. Homing runs towards the switch at a
// constant speed, reading the home line before each step, for at most 1.1 turns
// (fault 2 "home switch not found" otherwise).

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "capture/turntable.hpp"
#include "core/error.hpp"
#include "devices/gpio_lights.hpp"

namespace fest::devices {

struct GpioStepperConfig {
  std::string chip = "gpiochip0";
  std::string step, dir, en, home;  // line names or offsets; en, home optional
  std::uint32_t steps_per_rev = 3200;
  std::uint32_t max_speed = 2000;  // steps/s
  std::uint32_t max_accel = 4000;  // steps/s^2
  bool home_active_low = false, en_active_high = false;
};

// usage_error for unknown keys, missing step/dir, non-positive numbers.
GpioStepperConfig parse_gpio_stepper_uri(const std::string& uri);

class GpioStepper : public capture::Turntable {
 public:
  explicit GpioStepper(const GpioStepperConfig& config);
  ~GpioStepper() override;
  GpioStepper(const GpioStepper&) = delete;
  GpioStepper& operator=(const GpioStepper&) = delete;

  capture::TurntableInfo info() override;
  capture::TurntableStatus status() override;
  void move_abs(std::int32_t target, std::uint32_t speed_steps_s) override;
  void stop(bool immediate) override;
  void wait_ms(unsigned ms) override;
  void home(bool clockwise, std::uint32_t speed_steps_s) override;
  void set_zero() override;
  void enable(bool on) override;

  // False once a step train ran without SCHED_FIFO (not permitted: no CAP_SYS_NICE or
  // RLIMIT_RTPRIO), so the tool can warn that step timing may jitter.
  bool realtime() const { return realtime_; }

 private:
  void make_realtime();
  struct Lines;
  void halt(bool immediate);
  void run_move(std::int32_t target, double speed);
  void run_home(bool clockwise, double speed);
  void pulse(int direction);  // one STEP pulse; position += direction
  void fail(const Error& e);

  GpioStepperConfig config_;
  std::unique_ptr<Lines> lines_;
  std::thread worker_;
  std::mutex mutex_;  // guards everything below and the line writes
  std::atomic<std::int32_t> position_{0};
  std::atomic<int> stop_request_{0};
  std::atomic<bool> realtime_{true};  // 0 none, 1 decelerate, 2 immediate
  std::int32_t target_ = 0;
  capture::MotionState state_ = capture::MotionState::idle;
  bool homed_ = false, enabled_ = true;
  std::uint16_t fault_ = 0;
  std::uint32_t seq_ = 0;
  int dir_level_ = -1;  // last DIR written (-1: none yet)
  Status error_status_ = Status::ok;
  std::string error_;
};

}  // namespace fest::devices

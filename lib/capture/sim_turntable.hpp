#pragma once
// In-process turntable for tests and simulated sessions (URI `sim:...`, docs/capture.md
// §4.2). Deterministic: time is virtual and advances only through wait_ms(). The table
// (the object) follows the motor with gear backlash: after a reversal the motor must take
// up `backlash` degrees of play before the table moves again.
//
//   sim:[steps=51200,speed=90,backlash=0.2,fail_at=N,unplug_at=N]
//   speed in deg/s; fail_at: the N-th move command (1-based) never completes (the host
//   times out); unplug_at: from the N-th command of any kind on, every call reports the
//   device gone.

#include <string>

#include "capture/turntable.hpp"

namespace fest::capture {

struct SimTurntableConfig {
  std::uint32_t steps_per_rev = 51200;
  double speed_deg_s = 90;
  double backlash_deg = 0;
  int fail_at = 0;    // 0 = never
  int unplug_at = 0;  // 0 = never
};

// Parses "sim:" and its comma-separated key=value list; usage_error for unknown keys or
// bad values.
SimTurntableConfig parse_sim_turntable_uri(const std::string& uri);

class SimTurntable : public Turntable {
 public:
  explicit SimTurntable(SimTurntableConfig config);
  TurntableInfo info() override;
  TurntableStatus status() override;
  void move_abs(std::int32_t target, std::uint32_t speed_steps_s) override;
  void stop(bool immediate) override;
  void wait_ms(unsigned ms) override;
  // The simulator's "home switch" sits at step 0: homing is a move there.
  void home(bool clockwise, std::uint32_t speed_steps_s) override;
  void set_zero() override;
  void enable(bool on) override;

  // Where the object really is, in motor steps (the motor position minus the play not yet
  // taken up), and the virtual time.
  double table_position() const { return table_; }
  double elapsed_s() const { return clock_s_; }

 private:
  void count_command();
  SimTurntableConfig config_;
  double motor_ = 0, table_ = 0;
  std::int32_t target_ = 0;
  double speed_ = 0;  // steps/s of the current move
  bool stuck_ = false;
  int commands_ = 0;
  int moves_ = 0;
  bool unplugged_ = false;
  bool enabled_ = true;
  double clock_s_ = 0;
};

}  // namespace fest::capture

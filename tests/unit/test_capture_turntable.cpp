// Motion policy on the simulated turntable (docs/capture.md §6): executed angles are
// the commanded ones rounded to the nearest step (error <= 0.5 step), the ccw approach
// ends every move on the same side of the gear play whatever the direction it came from,
// a move that never completes times out (status 7) and an unplug reports status 5.

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "capture/sim_turntable.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;

fest::Status status_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    return e.status();
  }
  return fest::Status::ok;
}

TEST(CaptureTurntable, StepsRoundToNearest) {
  EXPECT_EQ(steps_for_angle(45.0, 51200), 6400);
  EXPECT_EQ(steps_for_angle(-90.0, 3200), -800);
  EXPECT_DOUBLE_EQ(angle_for_steps(6400, 51200), 45.0);
  for (double deg = 0; deg < 360; deg += 7.3) {
    const std::int32_t s = steps_for_angle(deg, 3200);
    EXPECT_LE(std::fabs(angle_for_steps(s, 3200) - deg), 0.5 * 360.0 / 3200 + 1e-12) << deg;
  }
}

TEST(CaptureTurntable, ParsesSimUri) {
  const SimTurntableConfig c = parse_sim_turntable_uri("sim:steps=3200,speed=45,backlash=0.2,fail_at=3,unplug_at=9");
  EXPECT_EQ(c.steps_per_rev, 3200u);
  EXPECT_DOUBLE_EQ(c.speed_deg_s, 45);
  EXPECT_DOUBLE_EQ(c.backlash_deg, 0.2);
  EXPECT_EQ(c.fail_at, 3);
  EXPECT_EQ(c.unplug_at, 9);
  EXPECT_EQ(parse_sim_turntable_uri("sim:").steps_per_rev, 51200u);
  EXPECT_EQ(status_of([] { parse_sim_turntable_uri("sim:warp=9"); }), fest::Status::usage);
  EXPECT_EQ(status_of([] { parse_sim_turntable_uri("sim:speed=-1"); }), fest::Status::usage);
  EXPECT_EQ(status_of([] { parse_sim_turntable_uri("usb:1209:0001"); }), fest::Status::usage);
}

TEST(CaptureTurntable, CcwApproachEndsOnTheSameSideOfThePlay) {
  SimTurntableConfig c;
  c.steps_per_rev = 3600;  // 10 steps per degree
  c.backlash_deg = 0.5;    // 5 steps of play
  SimTurntable table(c);
  MotionPolicy policy;     // ccw, 2 deg overshoot
  const double play = 5;
  for (double deg : {30.0, 10.0, 10.0, 50.0, 20.0, 20.5, 0.0}) {
    const MoveResult r = move_to_angle(table, deg, policy);
    EXPECT_EQ(r.steps, std::lround(deg * 10));
    EXPECT_EQ(table.status().position, r.steps);
    // Last leg moving up: the table sits `play` below the motor, every time.
    EXPECT_DOUBLE_EQ(table.table_position(), r.steps - play) << deg;
  }
}

TEST(CaptureTurntable, WithoutOvershootThePlayShows) {
  SimTurntableConfig c;
  c.steps_per_rev = 3600;
  c.backlash_deg = 0.5;
  SimTurntable table(c);
  MotionPolicy policy;
  policy.backlash_deg = 0;
  move_to_angle(table, 30, policy);
  EXPECT_DOUBLE_EQ(table.table_position(), 300 - 5.0);
  move_to_angle(table, 10, policy);  // came down: the table is at the motor
  EXPECT_DOUBLE_EQ(table.table_position(), 100);
}

TEST(CaptureTurntable, MoveTakesDistanceOverSpeed) {
  SimTurntableConfig c;
  c.steps_per_rev = 3600;
  c.speed_deg_s = 90;
  SimTurntable table(c);
  move_to_angle(table, 90, MotionPolicy{});
  // 90 deg at 90 deg/s in 20 ms polls: 1 s, plus at most one poll.
  EXPECT_NEAR(table.elapsed_s(), 1.0, 0.021);
}

TEST(CaptureTurntable, StuckMoveTimesOut) {
  SimTurntableConfig c;
  c.steps_per_rev = 3600;
  c.fail_at = 2;  // the second move command sticks
  SimTurntable table(c);
  move_to_angle(table, 10, MotionPolicy{});
  const double before = table.elapsed_s();
  EXPECT_EQ(status_of([&] { move_to_angle(table, 20, MotionPolicy{}); }), fest::Status::timeout);
  // distance / speed + 2 s of grace, then the host stops the table.
  EXPECT_NEAR(table.elapsed_s() - before, 10.0 / 90 + 2.0, 0.021);
  EXPECT_EQ(table.status().state, MotionState::idle);
}

TEST(CaptureTurntable, UnplugReportsDeviceNotFound) {
  SimTurntableConfig c;
  c.unplug_at = 10;
  SimTurntable table(c);
  EXPECT_EQ(status_of([&] { move_to_angle(table, 45, MotionPolicy{}); }), fest::Status::device_not_found);
  EXPECT_EQ(status_of([&] { table.status(); }), fest::Status::device_not_found);
}

}  // namespace

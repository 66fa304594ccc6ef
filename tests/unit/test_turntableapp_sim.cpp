// fest_turntable_app called with typed options on the simulator backend: the executed
// angle is a whole number of steps, steps = round(deg / 360 * S_rev) (docs/turntable.md §1),
// and a ccw approach to a lower angle overshoots and comes back (§2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"

namespace {

using namespace fest::turntable_tool;

nlohmann::json move_json(const std::string& uri, const MoveOptions& o) {
  DeviceOptions d;
  d.device = uri;
  d.json = true;
  testing::internal::CaptureStdout();
  const int rc = move_command(d, o);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(rc, 0);
  return nlohmann::json::parse(out);
}

TEST(TurntableApp, QuarterTurnIsAQuarterOfTheSteps) {
  MoveOptions o;
  o.degrees = 90;
  o.settle_ms = 0;
  const auto j = move_json("sim:steps=3200", o);
  EXPECT_EQ(j["steps"], 800);
  EXPECT_DOUBLE_EQ(j["angle_deg"].get<double>(), 90.0);
  EXPECT_EQ(j["overshoot"], false);
}

TEST(TurntableApp, CounterClockwiseApproachFromAboveOvershoots) {
  MoveOptions o;
  o.degrees = -45;
  o.settle_ms = 0;
  o.approach = Approach::ccw;
  EXPECT_EQ(move_json("sim:steps=3200", o)["overshoot"], true);
  o.approach = Approach::cw;
  const auto j = move_json("sim:steps=3200", o);
  EXPECT_EQ(j["steps"], -400);
  EXPECT_EQ(j["overshoot"], false);
}

}  // namespace

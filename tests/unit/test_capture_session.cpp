// The acquisition loop on simulated devices (docs/capture.md §2-3, docs/capture.md §6): during every
// hdr shot exactly the planned light is on; an unplugged table or a move that never
// completes ends the session with status 5 or 7 and every light off; a sink that already
// holds some shots gets only the others.

#include <set>

#include <gtest/gtest.h>

#include "capture/session.hpp"
#include "capture/sim_lights.hpp"
#include "capture/sim_turntable.hpp"

namespace {

using namespace fest::capture;

// A camera that records which lights were on at each picture, and the exposure.
class SpyCamera : public Camera {
 public:
  explicit SpyCamera(LightBank& lights) : lights_(lights) {}
  CameraInfo info() override { return {8, 8, 1, 8, "spy"}; }
  void set_exposure(double s) override { exposure = s; }
  fest::Image capture() override {
    std::vector<std::string> on;
    for (const LightState& l : lights_.list())
      if (l.on) on.push_back(l.id);
    lit.push_back(on);
    exposures.push_back(exposure);
    return fest::Image{cv::Mat(8, 8, CV_8UC1, cv::Scalar(0)), fest::ColorSpace::srgb};
  }
  double exposure = 0;
  std::vector<std::vector<std::string>> lit;
  std::vector<double> exposures;

 private:
  LightBank& lights_;
};

class MemorySink : public ShotSink {
 public:
  bool done(const PlannedShot& s) override { return have.count(s.file) > 0; }
  void store(const PlannedShot& s, const ShotPose& pose, const fest::Image&) override {
    stored.push_back(s);
    poses.push_back(pose);
  }
  std::set<std::string> have;
  std::vector<PlannedShot> stored;
  std::vector<ShotPose> poses;
};

std::vector<PlannedShot> plan_shots() {
  Plan p;
  p.angles_deg = {0, 90, 180, 270};
  p.lights = {"L0", "L1"};
  p.exposures_s = {0.001, 0.002, 0.004};
  p.silhouette = true;
  p.silhouette_lights = {"BG"};
  p.dark.count = 1;
  Station st;
  for (const char* id : {"L0", "L1", "BG"}) {
    LightConfig l;
    l.id = id;
    l.uri = "sim:";
    if (std::string(id) == "BG") l.role = "backlight";
    st.lights.push_back(l);
  }
  return expand_plan(p, st, ".png", "plan");
}

TEST(CaptureSession, ExactlyThePlannedLightsDuringEveryShot) {
  SimTurntable table(SimTurntableConfig{});
  SimLightBank lights({"L0", "L1", "BG"});
  SpyCamera camera(lights);
  MemorySink sink;
  const std::vector<PlannedShot> shots = plan_shots();
  const SessionOutcome out = run_session(table, lights, camera, shots, SessionOptions{}, sink);
  ASSERT_TRUE(out.complete) << out.message;
  ASSERT_EQ(sink.stored.size(), shots.size());
  ASSERT_EQ(camera.lit.size(), shots.size());
  for (std::size_t i = 0; i < shots.size(); ++i) {
    std::vector<std::string> want = shots[i].lights_on;
    EXPECT_EQ(camera.lit[i], want) << shots[i].file;
    EXPECT_DOUBLE_EQ(camera.exposures[i], shots[i].exposure_s) << shots[i].file;
    EXPECT_DOUBLE_EQ(sink.poses[i].angle_deg, shots[i].angle_cmd_deg);
  }
  for (const LightState& l : lights.list()) EXPECT_FALSE(l.on) << l.id;
  // The table really is at the commanded angle at each view (no backlash configured).
  EXPECT_NEAR(table.table_position(), 270.0 / 360 * 51200, 1e-9);
}

TEST(CaptureSession, UnplugEndsWithStatus5AndLightsOff) {
  SimTurntableConfig c;
  c.unplug_at = 30;  // some way into the second view's move
  SimTurntable table(c);
  SimLightBank lights({"L0", "L1", "BG"});
  SpyCamera camera(lights);
  MemorySink sink;
  const SessionOutcome out = run_session(table, lights, camera, plan_shots(), SessionOptions{}, sink);
  EXPECT_FALSE(out.complete);
  EXPECT_EQ(out.status, fest::Status::device_not_found);
  EXPECT_NE(out.failed_step.find("move to angle"), std::string::npos) << out.failed_step;
  EXPECT_GT(sink.stored.size(), 0u);
  for (const LightState& l : lights.list()) EXPECT_FALSE(l.on) << l.id;
  ASSERT_FALSE(lights.timeline().empty());
  EXPECT_FALSE(lights.timeline().back().on);
}

TEST(CaptureSession, StuckMoveTimesOutWithStatus7) {
  SimTurntableConfig c;
  c.fail_at = 2;
  SimTurntable table(c);
  SimLightBank lights({"L0", "L1", "BG"});
  SpyCamera camera(lights);
  MemorySink sink;
  const SessionOutcome out = run_session(table, lights, camera, plan_shots(), SessionOptions{}, sink);
  EXPECT_EQ(out.status, fest::Status::timeout);
  for (const LightState& l : lights.list()) EXPECT_FALSE(l.on) << l.id;
}

TEST(CaptureSession, ResumeTakesOnlyTheMissingShots) {
  const std::vector<PlannedShot> shots = plan_shots();
  SimTurntable table(SimTurntableConfig{});
  SimLightBank lights({"L0", "L1", "BG"});
  SpyCamera camera(lights);
  MemorySink sink;
  // Views 0 and 1 complete, view 2 half done.
  for (const PlannedShot& s : shots)
    if (s.angle_index < 2 || (s.angle_index == 2 && s.light == "L0")) sink.have.insert(s.file);
  const SessionOutcome out = run_session(table, lights, camera, shots, SessionOptions{}, sink);
  ASSERT_TRUE(out.complete);
  EXPECT_EQ(out.shots_skipped, int(sink.have.size()));
  EXPECT_EQ(std::size_t(out.shots_taken) + sink.have.size(), shots.size());
  for (const PlannedShot& s : sink.stored) EXPECT_EQ(sink.have.count(s.file), 0u) << s.file;
  // Only two views needed the table.
  EXPECT_EQ(sink.stored.front().angle_index, 2);
}

}  // namespace

// The journal and the manifest (docs/capture.md §2-3, fest-capture(5)): replay keeps the latest
// record per file, ignores a line torn by a crash at the very end, refuses damage
// elsewhere; the manifest lists the planned shots in plan order with their sets.

#include <gtest/gtest.h>

#include "capture/manifest.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;
using nlohmann::json;

PlannedShot hdr_shot(int angle, int k) {
  PlannedShot s;
  s.kind = ShotKind::hdr;
  s.angle_index = angle;
  s.angle_cmd_deg = 90.0 * angle;
  s.light = "L0";
  s.lights_on = {"L0"};
  s.exposure_index = k;
  s.exposure_s = 0.001 * (1 << k);
  s.file = fmt::format("a{:03}/L0/e{:02}.png", angle, k);
  return s;
}

ShotRecord record(const PlannedShot& s, char hash) {
  ShotRecord r;
  r.shot = s;
  r.pose = {s.angle_cmd_deg, std::int32_t(s.angle_index * 12800)};
  r.time = "2026-01-01T00:00:00.000Z";
  r.sha256 = std::string(64, hash);
  return r;
}

std::string journal_text(const std::vector<ShotRecord>& records) {
  std::string text = journal_line(journal_header("sess", "t0", json{{"angles_deg", {0}}}));
  for (const ShotRecord& r : records) text += journal_line({{"shot", shot_to_json(r)}});
  return text;
}

TEST(CaptureManifest, ShotRoundTrip) {
  const ShotRecord r = record(hdr_shot(2, 5), 'a');
  const ShotRecord back = shot_from_json(shot_to_json(r), "x", "shot");
  EXPECT_EQ(back.shot.file, r.shot.file);
  EXPECT_EQ(back.shot.exposure_index, 5);
  EXPECT_DOUBLE_EQ(back.shot.exposure_s, 0.032);
  EXPECT_EQ(back.pose.angle_steps, 25600);
  EXPECT_EQ(back.sha256, r.sha256);
}

TEST(CaptureManifest, RepeatIndexOnlyForLaterTakes) {
  PlannedShot take = hdr_shot(1, 3);
  EXPECT_FALSE(shot_to_json(record(take, 'a')).contains("repeat_index"));  // plans without repeat
  take.repeat_index = 2;
  take.file = "a001/L0/e03_r2.png";
  const json j = shot_to_json(record(take, 'a'));
  EXPECT_EQ(j["repeat_index"], 2);
  EXPECT_EQ(shot_from_json(j, "x", "shot").shot.repeat_index, 2);
}

TEST(CaptureManifest, ReplayKeepsLatestAndSkipsTornTail) {
  std::string text = journal_text({record(hdr_shot(0, 0), 'a'), record(hdr_shot(0, 1), 'b'), record(hdr_shot(0, 0), 'c')});
  text += journal_line({{"abort", {{"step", "move"}}}});
  text += journal_line({{"resume", "t1"}});
  const std::string whole = text;
  text += R"({"shot":{"file":"a000/L0/e02.png","ki)";  // crash in the middle of a write
  const Journal j = replay_journal(text, "manifest.journal");
  EXPECT_TRUE(j.torn_tail);
  EXPECT_EQ(j.records, 3);
  ASSERT_EQ(j.shots.size(), 2u);
  EXPECT_EQ(j.shots.at("a000/L0/e00.png").sha256, std::string(64, 'c'));
  EXPECT_EQ(j.header["session"], "sess");
  EXPECT_FALSE(replay_journal(whole, "j").torn_tail);
  // Damage before the end is not a torn write.
  std::string bad = whole;
  bad.insert(journal_line(journal_header("sess", "t0", json::object())).size(), "garbage\n");
  EXPECT_THROW(replay_journal(bad, "j"), fest::Error);
  EXPECT_THROW(replay_journal("{\"shot\": 1}\n", "j"), fest::Error);  // no header
  EXPECT_THROW(replay_journal("", "j"), fest::Error);
}

TEST(CaptureManifest, BuildsShotsInPlanOrderWithSets) {
  std::vector<PlannedShot> plan;
  PlannedShot sil;
  sil.kind = ShotKind::silhouette;
  sil.file = "a000/sil.png";
  sil.exposure_s = 0.01;
  plan.push_back(sil);
  for (int k = 0; k < 3; ++k) plan.push_back(hdr_shot(0, k));
  for (int k = 0; k < 3; ++k) plan.push_back(hdr_shot(1, k));
  std::map<std::string, ShotRecord> records;
  // Stored out of order (a resumed session): the manifest follows the plan.
  for (int i = int(plan.size()) - 1; i >= 0; --i) records[plan[std::size_t(i)].file] = record(plan[std::size_t(i)], 'd');
  records.erase("a001/L0/e01.png");  // not taken yet
  ManifestInfo info;
  info.session = "sess";
  const json m = build_manifest(info, plan, records);
  ASSERT_EQ(m["shots"].size(), 6u);
  EXPECT_EQ(m["shots"][0]["kind"], "silhouette");
  EXPECT_EQ(m["shots"][1]["file"], "a000/L0/e00.png");
  EXPECT_EQ(m["shots"][5]["file"], "a001/L0/e02.png");
  ASSERT_EQ(m["sets"].size(), 2u);
  EXPECT_EQ(m["sets"][0]["shots"], json({1, 2, 3}));
  EXPECT_EQ(m["sets"][1]["shots"], json({4, 5}));
  EXPECT_EQ(m["sets"][1]["angle_index"], 1);
  EXPECT_EQ(m["status"], "complete");
}

}  // namespace

// Plans (docs/capture.md §2-3): flag syntax, JSON forms, expansion into the acquisition
// order (mechanics outermost), checks against the station, errors naming file and path.

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "capture/plan.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;
using nlohmann::json;

Station station() {
  return parse_station(json::parse(R"({
    "camera": {"uri": "sim:"}, "turntable": {"uri": "sim:"},
    "lights": [{"id": "L0", "uri": "sim:", "position_mm": [1, 2, 3], "max_on_s": 10},
               {"id": "L1", "uri": "sim:", "position_mm": [1, 2, 3]},
               {"id": "BG", "uri": "sim:", "role": "backlight"}]})"),
                       "station.json");
}

std::string error_of(const json& doc) {
  try {
    parse_plan(doc, "plan.json");
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    return e.what();
  }
  return "";
}

TEST(CapturePlan, FlagForms) {
  const std::vector<double> a = angles_from_flag("24");
  ASSERT_EQ(a.size(), 24u);
  EXPECT_DOUBLE_EQ(a[3], 45.0);
  EXPECT_EQ(angles_from_flag("0,15,30").size(), 3u);
  const std::vector<double> t = exposures_from_flag("1/1000:1:12");
  ASSERT_EQ(t.size(), 12u);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], 0.001 * std::pow(2.0, double(k)), 1e-15);
  EXPECT_NEAR(exposures_from_flag("1/1000:0.5:3")[2], 0.002, 1e-15);
  EXPECT_THROW(exposures_from_flag("0.002,0.001"), fest::Error);
  EXPECT_THROW(angles_from_flag("0"), fest::Error);
  EXPECT_DOUBLE_EQ(seconds_from_text("1/250"), 0.004);
}

TEST(CapturePlan, ExpandsInAcquisitionOrder) {
  const Plan p = parse_plan(json::parse(R"({"angles_deg": {"count": 4}, "lights": "each",
      "exposures_s": {"base": 0.001, "stops": 1, "count": 3},
      "per_view": {"silhouette": {"lights_on": ["BG"], "exposure_s": 0.01}, "lightcal": {"count": 2}, "dark": {"count": 1}}})"),
                            "plan.json");
  const std::vector<PlannedShot> shots = expand_plan(p, station(), ".png", "plan.json");
  // Per view: 1 silhouette + 2 lightcal + 1 dark + 2 lights x 3 exposures = 10.
  ASSERT_EQ(shots.size(), 40u);
  EXPECT_EQ(shots[0].file, "a000/sil.png");
  EXPECT_EQ(shots[0].lights_on, std::vector<std::string>{"BG"});
  EXPECT_EQ(shots[1].file, "a000/lightcal_0.png");
  EXPECT_EQ(shots[2].light, "L1");  // lightcal k uses light k mod n
  EXPECT_EQ(shots[3].file, "a000/dark_0.png");
  EXPECT_TRUE(shots[3].lights_on.empty());
  EXPECT_EQ(shots[4].file, "a000/L0/e00.png");
  EXPECT_EQ(shots[9].file, "a000/L1/e02.png");
  EXPECT_DOUBLE_EQ(shots[9].exposure_s, 0.004);
  EXPECT_EQ(shots[10].file, "a001/sil.png");
  EXPECT_DOUBLE_EQ(shots[10].angle_cmd_deg, 90.0);
  for (std::size_t i = 1; i < shots.size(); ++i) EXPECT_GE(shots[i].angle_index, shots[i - 1].angle_index);
  // The JSON written by plan_to_json parses back to the same expansion.
  const Plan again = parse_plan(plan_to_json(p), "again");
  EXPECT_EQ(expand_plan(again, station(), ".png", "again").size(), shots.size());
}

TEST(CapturePlan, ErrorsNameFileAndPath) {
  EXPECT_NE(error_of(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.1], "expsoures": 1})"))
                .find("unknown key \"expsoures\""),
            std::string::npos);
  const std::string e = error_of(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.1, -1]})"));
  EXPECT_NE(e.find("exposures_s"), std::string::npos) << e;
  EXPECT_NE(e.find("plan.json"), std::string::npos) << e;
  EXPECT_NE(error_of(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.1], "auto_bracket": true})"))
                .find("not supported"),
            std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.1],
                                     "per_view": {"silhouette": {"lights": ["BG"]}}})"))
                .find("per_view.silhouette"),
            std::string::npos);
  // Against the station: an unknown light, and L0's thermal limit (10 s) under a 16 s series.
  const Plan unknown = parse_plan(json::parse(R"({"angles_deg": [0], "lights": ["L7"], "exposures_s": [0.1]})"), "p");
  EXPECT_THROW(expand_plan(unknown, station(), ".png", "p"), fest::Error);
  const Plan hot = parse_plan(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [8, 8.5]})"), "p");
  try {
    expand_plan(hot, station(), ".png", "p");
    FAIL();
  } catch (const fest::Error& err) {
    EXPECT_NE(std::string(err.what()).find("max_on_s"), std::string::npos) << err.what();
  }
}

TEST(CapturePlan, RepeatTakesEveryExposureBackToBack) {
  const Plan p = parse_plan(
      json::parse(R"({"angles_deg": [0, 90], "lights": ["L0"], "exposures_s": [0.01, 0.02], "repeat": 3,
                      "per_view": {"dark": {"count": 1}}})"),
      "p");
  EXPECT_EQ(p.repeat, 3);
  EXPECT_EQ(plan_to_json(p)["repeat"], 3);
  const std::vector<PlannedShot> shots = expand_plan(p, station(), ".png", "p");
  // Per view: 1 dark frame (not repeated) + 2 exposures x 3 takes.
  ASSERT_EQ(shots.size(), 2u * (1 + 2 * 3));
  EXPECT_EQ(shots[0].file, "a000/dark_0.png");
  const char* files[] = {"a000/L0/e00_r0.png", "a000/L0/e00_r1.png", "a000/L0/e00_r2.png",
                         "a000/L0/e01_r0.png", "a000/L0/e01_r1.png", "a000/L0/e01_r2.png"};
  for (int i = 0; i < 6; ++i) {
    const PlannedShot& s = shots[std::size_t(1 + i)];
    EXPECT_EQ(s.file, files[i]);
    EXPECT_EQ(s.exposure_index, i / 3);
    EXPECT_EQ(s.repeat_index, i % 3);
    EXPECT_DOUBLE_EQ(s.exposure_s, i < 3 ? 0.01 : 0.02);
  }
  EXPECT_EQ(shots[7].file, "a001/dark_0.png");
  // repeat 1 keeps the plain names.
  const Plan once = parse_plan(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.01]})"), "p");
  EXPECT_EQ(once.repeat, 1);
  EXPECT_EQ(expand_plan(once, station(), ".png", "p")[0].file, "a000/L0/e00.png");
  // The thermal limit counts every take: 3 x 4 s = 12 s > L0's max_on_s 10 s.
  const Plan hot = parse_plan(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [4], "repeat": 3})"), "p");
  EXPECT_THROW(expand_plan(hot, station(), ".png", "p"), fest::Error);
  EXPECT_NE(error_of(json::parse(R"({"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.1], "repeat": 0})")).find("repeat"),
            std::string::npos);
}

TEST(CaptureStation, ErrorsNameFileAndPath) {
  try {
    parse_station(json::parse(R"({"camera": {"uri": "sim:"}, "turntable": {"uri": "sim:"},
                                  "lights": [{"id": "L0", "uri": "sim:", "position_mm": [1, 2]}]})"),
                  "station.json");
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("lights[0].position_mm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("station.json"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_station(json::parse(R"({"camera": {"uri": "sim:"}, "turntable": {"uri": "sim:", "calibration":
      {"R_T0": [1, 0, 0, 0, 2, 0, 0, 0, 1], "t_T0": [0, 0, 0]}}, "lights": []})"), "s"), fest::Error);
  const Station s = station();
  EXPECT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.turntable.settle_ms, 500u);
}

}  // namespace

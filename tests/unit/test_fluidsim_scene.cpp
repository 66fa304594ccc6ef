// Scene validation (fluidsim(1); bad input as README "Conventions" asks).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "expect_error.hpp"
#include "fluidsim/scene.hpp"

using namespace fest::fluidsim;
using fest::test::expect_bad_input;
using nlohmann::json;

TEST(FluidsimScene, DefaultsAreThoseOfTheManPage) {
  const Scene s = parse_scene(json::parse(R"({"dims": [31, 15, 15]})"), "s.json");
  EXPECT_EQ(s.dim, 3);
  EXPECT_DOUBLE_EQ(s.frame_dt, 0.04);
  EXPECT_EQ(s.interp, 1);
  EXPECT_EQ(s.frames, 100);
  ASSERT_EQ(s.scalars.size(), 1u);
  EXPECT_EQ(s.scalars[0].name, "density");
  const Layout L = s.layout();
  EXPECT_DOUBLE_EQ(L.h, 1.0 / 32);  // 1/(n_max + 1) on a closed box
  EXPECT_EQ(L.size[0], 33);
}

TEST(FluidsimScene, UnknownKeysGetAHint) {
  expect_bad_input([] { parse_scene(json::parse(R"({"dims": [8, 8], "viscocity": 1})"), "s.json"); },
                   "scene key \"viscocity\" is unknown (did you mean \"viscosity\"?) (s.json)");
  expect_bad_input([] { parse_scene(json::parse(R"({"dims": [8, 8], "zzzzzzzz": 1})"), "s.json"); },
                   "scene key \"zzzzzzzz\" is unknown (s.json)");
  expect_bad_input(
      [] { parse_scene(json::parse(R"({"dims": [8, 8], "scalars": [{"name": "d", "kapa": 1}]})"), "s.json"); },
      "did you mean \"kappa\"");
}

TEST(FluidsimScene, BadValuesAreRejected) {
  for (const char* doc : {R"({"dims": [8]})", R"({"dims": [8, 8, 8, 8]})", R"({"dims": [0, 8]})",
                          R"({"dims": [2000, 8]})", R"({"dims": [8.5, 8]})"})
    expect_bad_input([&] { parse_scene(json::parse(doc), "s.json"); }, "dims must be 2 or 3 integers in [3, 1024] (s.json: dims)");
  expect_bad_input([] { parse_scene(json::parse(R"({"dims": [8, 8], "viscosity": -1})"), "s"); }, "viscosity");
  expect_bad_input([] { parse_scene(json::parse(R"({"dims": [8, 8], "frame_dt": 0})"), "s"); }, "frame_dt");
  expect_bad_input([] { parse_scene(json::parse(R"({"dims": [8, 8], "interp": 0})"), "s"); }, "interp");
  expect_bad_input(
      [] {
        parse_scene(json::parse(R"({"dims": [8, 8], "scalars": [{"sources": [{"min": [20, 20], "max": [30, 30]}]}]})"), "s");
      },
      "outside the grid");
}

TEST(FluidsimScene, PartlyOutsideSourcesAreClippedWithAWarning) {
  const Scene s = parse_scene(
      json::parse(R"({"dims": [8, 8], "scalars": [{"sources": [{"min": [5, 5], "max": [30, 6], "rate": 1}]}]})"), "s");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_DOUBLE_EQ(s.scalars[0].sources[0].max[0], 9.0);
}

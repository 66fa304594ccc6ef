// hdrmerge session's manifest reader (tools/hdrmerge/session_manifest): what it accepts,
// grouped as capture writes it, and the bad manifests it refuses before any file is read.

#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "session_manifest.hpp"

namespace {

using fest::hdrmerge_tool::parse_session_manifest;
using nlohmann::json;

json shot(const char* file, double t, int angle, const char* kind = "hdr") {
  return json{{"file", file}, {"sha256", "00"}, {"exposure_s", t}, {"angle_index", angle}, {"angle_deg", 30.0 * angle},
              {"kind", kind}};
}

// Numbers as a parser makes them: non-negative integers are unsigned.
json manifest() {
  return json{{"version", 1},
              {"status", "complete"},
              {"session", "s"},
              {"shots", json::array({shot("a.png", 0.01, 0, "hdr"), shot("b.png", 0.01, 0, "hdr"),
                                     shot("c.png", 0.04, 0, "hdr"), shot("m.png", 0.01, 1, "silhouette")})},
              {"sets", json::array({json{{"light", "L0"}, {"shots", json::array({0u, 1u, 2u})}}})}};
}

std::string refusal(const json& m) {
  try {
    parse_session_manifest(m, "m.json");
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    return e.what();
  }
  return "accepted";
}

}  // namespace

// Two takes at 0.01 s then one at 0.04 s: two exposures, the first with two takes.
TEST(HdrmergeSessionManifest, GroupsTakesOfOneExposure) {
  const auto m = parse_session_manifest(manifest(), "m.json");
  ASSERT_EQ(m.sets.size(), 1u);
  ASSERT_EQ(m.sets[0].exposures.size(), 2u);
  EXPECT_EQ(m.sets[0].exposures[0].size(), 2u);
  EXPECT_EQ(m.sets[0].exposures[1][0].file, "c.png");
  EXPECT_EQ(m.session, "s");
  ASSERT_EQ(m.silhouettes.count(1), 1u);
  EXPECT_EQ(m.silhouettes.at(1).file, "m.png");
}

TEST(HdrmergeSessionManifest, RefusesWhatItCannotUse) {
  json m = manifest();
  m["status"] = "running";
  EXPECT_NE(refusal(m).find("not complete"), std::string::npos);
  m = manifest();
  m["sets"][0]["shots"] = json::array({0u, 1u});  // one exposure time only
  EXPECT_NE(refusal(m).find("at least 2"), std::string::npos);
  m = manifest();
  m["sets"][0]["shots"] = json::array({0u, 9u});
  EXPECT_NE(refusal(m).find("out of range"), std::string::npos);
  m = manifest();
  m["shots"][2]["file"] = "../etc/passwd";
  EXPECT_NE(refusal(m).find("inside the session"), std::string::npos);
  m = manifest();
  m["sets"][0]["light"] = "a/b";
  EXPECT_NE(refusal(m).find("not a light id"), std::string::npos);
  m = manifest();
  m["shots"][0]["angle_index"] = 1e300;
  EXPECT_NE(refusal(m).find("angle_index"), std::string::npos);
  m = manifest();
  m["shots"][1] = 7;  // not an object
  EXPECT_NE(refusal(m).find("shots[1]"), std::string::npos);
  m = manifest();
  m["version"] = 2;
  EXPECT_NE(refusal(m).find("version 1"), std::string::npos);
}

// The "lights" array of station.json (devices/station_lights): the keys the backends
// need, the known keys that belong to capture, and errors that name the JSON path.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "devices/station_lights.hpp"

namespace {

using namespace fest;
using nlohmann::json;

std::string error_of(const json& station) {
  try {
    devices::lights_from_station(station, "st.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    return e.what();
  }
  return "";
}

TEST(DevicesStation, ReadsTheSpecExample) {
  const json st = json::parse(R"({ "camera": {"uri": "v4l2:/dev/video0"},
    "lights": [ {"id": "L0", "uri": "gpio:chip=gpiochip0,line=GPIO17", "active_low": false,
                 "position_mm": [412.0, -80.5, 350.2], "intensity": [1.0, 0.97, 0.91],
                 "warmup_ms": 300, "max_on_s": 120},
                {"id": "BG", "uri": "gpio:chip=gpiochip0,line=GPIO27", "role": "backlight", "active_low": true} ] })");
  const auto l = devices::lights_from_station(st, "st.json");
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].id, "L0");
  EXPECT_EQ(l[0].uri, "gpio:chip=gpiochip0,line=GPIO17");
  EXPECT_FALSE(l[0].active_low);
  EXPECT_EQ(l[1].id, "BG");
  EXPECT_TRUE(l[1].active_low);
}

TEST(DevicesStation, ErrorsNameFileAndPath) {
  EXPECT_NE(error_of(json::parse(R"({"lights": [{"id": "A", "uri": "sim:", "colour": 3}]})")).find("\"colour\""), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"lights": [{"id": "A", "uri": "sim:"}, {"uri": "sim:"}]})")).find("st.json: /lights/1/id"),
            std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"lights": [{"id": "A"}]})")).find("/lights/0/uri"), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"lights": {"id": "A"}})")).find("/lights"), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"turntable": {}})")).find("no \"lights\""), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"([1])")).find("object"), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"lights": [{"id": "A", "uri": "sim:"}, {"id": "A", "uri": "sim:"}]})")).find("twice"),
            std::string::npos);
}

}  // namespace

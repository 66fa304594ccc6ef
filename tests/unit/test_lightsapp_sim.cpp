// fest_lights_app called with typed options on a station of simulated lights: list gives
// the station's lights in its order, all off (a simulated light starts off, docs/lights.md
// §3); an unknown id is a usage error naming it; a pulse lasts at least its duration.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "commands.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::lights_tool;

class LightsApp : public testing::Test {
 protected:
  void SetUp() override {
    path_ = std::filesystem::temp_directory_path() / ("fest_lightsapp_" + std::to_string(::getpid()) + ".json");
    std::ofstream(path_) << R"({ "lights": [ {"id": "L0", "uri": "sim:"}, {"id": "BG", "uri": "sim:", "role": "backlight"} ] })";
    station_.station = path_.string();
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::filesystem::path path_;
  StationOptions station_;
};

TEST_F(LightsApp, ListsTheStationInOrderAllOff) {
  testing::internal::CaptureStdout();
  EXPECT_EQ(list_command(station_), 0);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "id,uri,state\nL0,sim:,off\nBG,sim:,off\n");
}

TEST_F(LightsApp, UnknownIdIsAUsageErrorNamingIt) {
  try {
    on_command(station_, {"L0", "L7"});
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    EXPECT_NE(std::string(e.what()).find("'L7'"), std::string::npos) << e.what();
  }
}

TEST_F(LightsApp, PulseLastsItsDuration) {
  PulseOptions p;
  p.id = "BG";
  p.ms = 30;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(pulse_command(station_, p), 0);
  EXPECT_GE(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(30));
}

}  // namespace

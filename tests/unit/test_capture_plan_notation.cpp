// The angle and bracket notations of lib/capture/plan (what `capture plan --angles` and
// `--bracket` are written in): their errors speak of angles and exposures, not of flags
// (the tool adds the flag's name), and the defaults of capture plan come from
// even_angles and bracket_exposures.

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "capture/plan.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;

std::string usage_message(const std::string& angles, const std::string& bracket) {
  try {
    if (!angles.empty()) angles_from_flag(angles);
    if (!bracket.empty()) exposures_from_flag(bracket);
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    return e.what();
  }
  ADD_FAILURE() << "no error for '" << angles << "' '" << bracket << "'";
  return {};
}

}  // namespace

TEST(CapturePlanNotation, ErrorsInTheDomainsTerms) {
  for (const auto& [angles, bracket] : std::vector<std::pair<std::string, std::string>>{
           {"0", ""}, {"0,x", ""}, {"", "1/1000:1"}, {"", "1/1000:9:3"}, {"", "0.002,0.001"}, {"", "1/0:1:3"}}) {
    const std::string m = usage_message(angles, bracket);
    EXPECT_EQ(m.find("--"), std::string::npos) << m;
  }
  EXPECT_NE(usage_message("0", "").find("turntable angle count"), std::string::npos);
  EXPECT_NE(usage_message("", "1/1000:9:3").find("bracket stops"), std::string::npos);
}

TEST(CapturePlanNotation, DefaultsAreTheNotationsDefaults) {
  EXPECT_EQ(even_angles(24), angles_from_flag("24"));
  EXPECT_EQ(bracket_exposures(1.0 / 1000, 1, 12), exposures_from_flag("1/1000:1:12"));
}

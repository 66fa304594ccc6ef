// Inputs that once broke fluidsim's decoders under fuzz_fluidsim (tests/data/regress/
// fluidsim/, named for what they exercise): frame streams ("NRRD...") and scenes. Each
// must now fail with one bad_input error.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "expect_error.hpp"
#include "fluidsim/frame.hpp"
#include "fluidsim/scene.hpp"
#include "testdata.hpp"

TEST(FluidsimRegress, FuzzFindingsAreBadInput) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/fluidsim"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = fest::test::slurp(entry.path().string());
    fest::test::expect_bad_input([&] {
      if (bytes.rfind("NRRD", 0) == 0) {
        std::size_t pos = 0;
        long n = 0;
        while (pos < bytes.size()) {
          fest::fluidsim::Frame f;
          pos = fest::fluidsim::decode_frame(bytes, pos, f, "regress", n++);
        }
      } else {
        fest::fluidsim::parse_scene(nlohmann::json::parse(bytes), "regress");
      }
    });
    ++replayed;
  }
  EXPECT_GE(replayed, 4);
}

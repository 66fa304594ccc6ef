// Pyramids that once broke the .tlp tile decoder under fuzz_tlp_pyramid (tests/data/regress/
// terrainlod/, named for what they exercise: Rice residuals that overflowed 64-bit height
// sums, a lattice whose parent surface asked for 32 GiB): each is opened and every tile
// decoded as the fuzz target does, and must end in one bad_input error.
#include <filesystem>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "pyramid_file.hpp"
#include "testdata.hpp"

TEST(TerrainlodRegress, FuzzFindingsAreBadInput) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/terrainlod"))) {
    SCOPED_TRACE(entry.path().filename().string());
    fest::test::expect_bad_input([&] {
      fest::terrainlod_tool::PyramidFile pyr{fest::test::slurp(entry.path().string()), entry.path().filename().string()};
      for (const auto& e : pyr.index()) pyr.tile(e.id);
    });
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}

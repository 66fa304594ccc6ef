// The pyramid flags' usage errors come from the tool (pyramid_options.cpp), naming the
// flag; lib/terrainlod says the same in its own terms. The texts users see are the ones
// the library produced before issue 20 moved them.

#include <gtest/gtest.h>

#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "expect_error.hpp"
#include "pyramid_options.hpp"
#include "terrainlod/pyramid_plan.hpp"

namespace {

using namespace fest::terrainlod_tool;

using fest::test::usage_message;

TEST(TerrainlodAppOptions, TileFlagsAreNamed) {
  EXPECT_EQ(usage_message([] { check_tile_options(48, 0, 1.0); }), "--tile must be a power of two between 4 and 4096 (got 48)");
  EXPECT_EQ(usage_message([] { check_tile_options(64, 48, 1.0); }), "--texels must be a power of two (got 48)");
  EXPECT_EQ(usage_message([] { check_tile_options(64, 32, 1.0); }), "--texels (32) must be at least --tile (64)");
  EXPECT_EQ(usage_message([] { check_tile_options(64, 0, 0.0); }), "--error-fraction must be a positive number (got 0)");
  EXPECT_NO_THROW(check_tile_options(64, 0, 1.0));
}

TEST(TerrainlodAppOptions, QuantumFlagsAreNamed) {
  EXPECT_EQ(usage_message([] { check_quantum_options(2.0, 0.0); }), "--height-quantum must be in (0, 1] (got 2)");
  EXPECT_EQ(usage_message([] { check_quantum_options(0.25, -1.0); }), "--leaf-error must be a finite number >= 0 (got -1)");
  EXPECT_NO_THROW(check_quantum_options(0.25, 0.0));
}

// Whatever the tool accepts, the library accepts: the two checks agree.
TEST(TerrainlodAppOptions, ToolAndLibraryAgree) {
  for (int tile : {2, 4, 48, 64, 4096, 8192})
    for (int texels : {0, 32, 64, 128, 65536, 131072}) {
      bool tool_ok = true, lib_ok = true;
      try {
        check_tile_options(tile, texels, 1.0);
      } catch (const fest::Error&) {
        tool_ok = false;
      }
      fest::terrainlod::PyramidParams p;
      p.tile = tile;
      p.texels = texels;
      try {
        fest::terrainlod::plan_pyramid(2, 2, 1, 1, p);
      } catch (const fest::Error&) {
        lib_ok = false;
      }
      EXPECT_EQ(tool_ok, lib_ok) << tile << " " << texels;
    }
}

TEST(TerrainlodAppOptions, TileIds) {
  const auto id = parse_tile("2/3/1");
  EXPECT_EQ(id.level, 2);
  EXPECT_EQ(id.x, 3);
  EXPECT_EQ(id.y, 1);
  EXPECT_EQ(usage_message([] { parse_tile("1/x/0"); }), "--tile expects L/X/Y (got '1/x/0')");
}

}  // namespace

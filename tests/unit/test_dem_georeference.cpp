// formats/dem read_georeference: the georeference of rasters of any band count (texture
// images draped over DEMs), in read_dem's convention (centre of the south-west pixel).

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "formats/dem/dem_io.hpp"

namespace {

std::string temp_file(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(DemGeoreference, SameConventionAsTheDemReader) {
  const std::string path = temp_file("georef_test.asc", "ncols 3\nnrows 2\nxllcorner 100\nyllcorner 200\ncellsize 10\n1 2 3\n4 5 6\n");
  const auto g = fest::formats::read_georeference(path);
  const auto r = fest::formats::read_dem(path);
  ASSERT_TRUE(g.georeferenced);
  EXPECT_EQ(g.width, 3);
  EXPECT_EQ(g.height, 2);
  EXPECT_DOUBLE_EQ(g.origin_x, r.origin_x);
  EXPECT_DOUBLE_EQ(g.origin_y, r.origin_y);
  EXPECT_DOUBLE_EQ(g.dx, 10);
  EXPECT_DOUBLE_EQ(g.dy, 10);
  std::remove(path.c_str());
}

TEST(DemGeoreference, AThreeBandImageWithAndWithoutAWorldFile) {
  // Raw PPM, 4 x 2 RGB pixels: three bands, which read_dem refuses.
  const std::string path = temp_file("georef_rgb.ppm", std::string("P6\n4 2\n255\n") + std::string(24, '\x40'));
  EXPECT_THROW(fest::formats::read_dem(path), fest::Error);
  const auto plain = fest::formats::read_georeference(path);
  EXPECT_FALSE(plain.georeferenced);
  EXPECT_EQ(plain.width, 4);
  EXPECT_EQ(plain.height, 2);
  // World file: 2 m pixels, top-left pixel centred on (1001, 2003).
  const std::string wld = temp_file("georef_rgb.wld", "2\n0\n0\n-2\n1001\n2003\n");
  const auto g = fest::formats::read_georeference(path);
  ASSERT_TRUE(g.georeferenced);
  EXPECT_DOUBLE_EQ(g.dx, 2);
  EXPECT_DOUBLE_EQ(g.dy, 2);
  EXPECT_DOUBLE_EQ(g.origin_x, 1001);  // the western column's centre
  EXPECT_DOUBLE_EQ(g.origin_y, 2001);  // the southern row's centre: one row below the top
  std::remove(wld.c_str());
  std::remove(path.c_str());
}

TEST(DemGeoreference, MissingFileIsAnIoErrorAndGarbageBadInput) {
  try {
    fest::formats::read_georeference(::testing::TempDir() + "georef_missing.tif");
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::io);
  }
  const std::string junk = temp_file("georef_junk.bin", "no raster here\n");
  fest::test::expect_bad_input([&] { fest::formats::read_georeference(junk); }, "georef_junk.bin");
  std::remove(junk.c_str());
}

}  // namespace

// formats/dem: .npy parsed by hand-built bytes, ESRI ASCII grids and GeoTIFF via GDAL.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "formats/dem/dem_io.hpp"

namespace {

std::string npy(const std::string& descr, const std::string& shape, const std::string& data) {
  std::string header = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  while ((10 + header.size() + 1) % 64) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  return out + header + data;
}

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(DemNpy, Int16RowsAndColumns) {
  const short v[6] = {1, 2, 3, -4, 500, 6};
  const auto r = fest::formats::read_npy(npy("<i2", "(2, 3)", std::string(reinterpret_cast<const char*>(v), 12)));
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  EXPECT_TRUE(r.integer);
  EXPECT_EQ(r.values[3], -4);
  EXPECT_EQ(r.values[4], 500);
}

TEST(DemNpy, TruncatedAndWrongShapes) {
  fest::test::expect_bad_input([] { fest::formats::read_npy(npy("<f4", "(2, 3)", std::string(20, '\0'))); },
                               "truncated");
  fest::test::expect_bad_input([] { fest::formats::read_npy(npy("<f4", "(6,)", std::string(24, '\0'))); }, "2-D");
  fest::test::expect_bad_input([] { fest::formats::read_npy(npy(">f4", "(1, 1)", std::string(4, '\0'))); },
                               "not supported");
}

TEST(DemGdal, AsciiGridGeoreferenceAndNodata) {
  const std::string path = temp_file("dem_test.asc",
                                     "ncols 3\nnrows 2\nxllcorner 100\nyllcorner 200\ncellsize 10\n"
                                     "NODATA_value -9999\n1 2 -9999\n4 5 6\n");
  const auto r = fest::formats::read_dem(path);
  EXPECT_EQ(r.format, "AAIGrid");
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  ASSERT_TRUE(r.georeferenced);
  EXPECT_DOUBLE_EQ(r.origin_x, 105);  // centre of the south-west cell
  EXPECT_DOUBLE_EQ(r.origin_y, 205);
  EXPECT_DOUBLE_EQ(r.dx, 10);
  EXPECT_EQ(r.nodata_count, 1u);
  EXPECT_TRUE(std::isnan(r.values[2]));
  EXPECT_EQ(r.values[3], 4);
  std::remove(path.c_str());
}

// GDAL alone reads these as 0 in an integer grid.
TEST(DemGdal, AsciiGridNonNumericMissingAndNanValues) {
  const std::string header = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
  const std::string word = temp_file("dem_word.asc", header + "1 2 3\n4 abc 6\n");
  fest::test::expect_bad_input([&] { fest::formats::read_dem(word); }, "non-numeric value 'abc' at row 2, column 2");
  const std::string short_ = temp_file("dem_short.asc", header + "1 2 3\n4 5\n");
  fest::test::expect_bad_input([&] { fest::formats::read_dem(short_); }, "has 5 of its 3 x 2 values");
  const std::string inf = temp_file("dem_inf.asc", header + "1 2 3\n4 inf 6\n");
  fest::test::expect_bad_input([&] { fest::formats::read_dem(inf); }, "infinite value at row 2, column 2");
  const std::string nan = temp_file("dem_nan.asc", header + "1 2 3\n4 nan 6\n");
  const auto r = fest::formats::read_dem(nan);
  EXPECT_EQ(r.nan_count, 1u);
  EXPECT_TRUE(std::isnan(r.values[4]));
  EXPECT_EQ(r.values[5], 6);
  for (const auto& p : {word, short_, inf, nan}) std::remove(p.c_str());
}

TEST(DemGdal, GarbageAndEmptyAreBadInput) {
  const std::string junk = temp_file("dem_junk.bin", "this is no raster at all\n");
  fest::test::expect_bad_input([&] { fest::formats::read_dem(junk); }, "dem_junk.bin");
  const std::string empty = temp_file("dem_empty.asc", "");
  fest::test::expect_bad_input([&] { fest::formats::read_dem(empty); }, "empty file");
  std::remove(junk.c_str());
  std::remove(empty.c_str());
}

}  // namespace

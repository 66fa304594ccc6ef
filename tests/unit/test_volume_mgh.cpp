// FreeSurfer MGH: headers built byte by byte from the layout in formats/volume/mgh.hpp,
// the placement formula world = Mdc^T diag(spacing) (ijk - dims/2) + c_ras, the default
// placement of goodRASFlag 0, the TR footer, the writer's types, and malformed headers.
#include <cstring>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/volume/volume_io.hpp"
#include "expect_error.hpp"

using fest::ScalarType;
using fest::Volume;
using fest::formats::Format;
using fest::formats::read_volume;
using fest::formats::write_volume;
using fest::test::expect_bad_input;

namespace {

void be32(std::string& b, std::size_t off, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[off + i] = static_cast<char>((v >> (24 - 8 * i)) & 0xff);
}
void bef(std::string& b, std::size_t off, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  be32(b, off, u);
}

// 4x3x2, 2 frames, int16 value = index - 10; spacing (2, 3, 4); axes: i -> -x (L),
// j -> +z (S), k -> -y (P) (FreeSurfer's coronal "conformed" order); c_ras (10, 20, 30);
// TR 2000 ms.
std::string mgh_bytes() {
  std::string b(284, '\0');
  be32(b, 0, 1);
  be32(b, 4, 4);
  be32(b, 8, 3);
  be32(b, 12, 2);
  be32(b, 16, 2);
  be32(b, 20, 4);  // MRI_SHORT
  b[29] = 1;       // goodRASFlag
  bef(b, 30, 2), bef(b, 34, 3), bef(b, 38, 4);
  const float mdc[9] = {-1, 0, 0, 0, 0, 1, 0, -1, 0};
  for (int i = 0; i < 9; ++i) bef(b, 42 + 4 * static_cast<std::size_t>(i), mdc[i]);
  bef(b, 78, 10), bef(b, 82, 20), bef(b, 86, 30);
  for (int i = 0; i < 48; ++i) {
    const auto v = static_cast<std::uint16_t>(static_cast<std::int16_t>(i - 10));
    b += static_cast<char>(v >> 8);
    b += static_cast<char>(v & 0xff);
  }
  std::string footer(20, '\0');
  bef(footer, 0, 2000.0f);
  return b + footer;
}

}  // namespace

TEST(VolumeMgh, HeaderFormulaGivesValuesAndPlacement) {
  const Volume v = read_volume(mgh_bytes(), Format::mgh);
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{4, 3, 2}));
  EXPECT_EQ(v.frames, 2u);
  EXPECT_EQ(v.type, ScalarType::i16);
  EXPECT_EQ(v.voxels[47], 37.0);
  EXPECT_EQ(v.voxels[0], -10.0);
  EXPECT_EQ(v.frame_spacing, 2.0);  // seconds
  EXPECT_EQ(v.spacing, (std::array<double, 3>{2, 3, 4}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, 0, -1, 0, 1, 0}));
  // Voxel dims/2 = (2, 1.5, 1) lies at c_ras.
  const auto c = v.world(2, 1.5, 1);
  EXPECT_EQ(c, (std::array<double, 3>{10, 20, 30}));
  // origin = c_ras - (-2*2, -4*1, 3*1.5) per world axis.
  EXPECT_EQ(v.origin, (std::array<double, 3>{14, 24, 25.5}));
}

TEST(VolumeMgh, WithoutGoodRasFlagThePlacementIsFreeSurfersDefault) {
  std::string b = mgh_bytes();
  b[29] = 0;
  const Volume v = read_volume(b, Format::mgh);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, 0, -1, 0, 1, 0}));
  EXPECT_EQ(v.world(2, 1.5, 1), (std::array<double, 3>{0, 0, 0}));
}

TEST(VolumeMgh, WriterRoundTripsAndWidensOnlyWithoutLoss) {
  const Volume v = read_volume(mgh_bytes(), Format::mgh);
  const Volume back = read_volume(write_volume(v, Format::mgh), Format::mgh);
  EXPECT_EQ(back.voxels, v.voxels);
  EXPECT_EQ(back.origin, v.origin);
  EXPECT_EQ(back.direction, v.direction);
  EXPECT_EQ(back.frame_spacing, v.frame_spacing);
  Volume u16 = v;
  u16.type = ScalarType::u16;
  for (double& x : u16.voxels) x += 65000;
  const Volume wide = read_volume(write_volume(u16, Format::mgh), Format::mgh);
  EXPECT_EQ(wide.type, ScalarType::i32);
  EXPECT_EQ(wide.voxels, u16.voxels);
  Volume f64 = v;
  f64.type = ScalarType::f64;
  expect_bad_input([&] { write_volume(f64, Format::mgh); }, "--type");
}

TEST(VolumeMghMalformed, EveryHeaderFieldIsChecked) {
  const std::string good = mgh_bytes();
  expect_bad_input([&] { read_volume(good.substr(0, 60), Format::mgh); }, "header needs");
  std::string b = good;
  be32(b, 0, 2);
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "version");
  b = good;
  be32(b, 8, 0);
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "height = 0");
  b = good;
  be32(b, 16, 0x7fffffff);
  be32(b, 12, 0x7fffffff);
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "limit");
  b = good;
  be32(b, 20, 10);
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "MRI_USHRT");
  be32(b, 20, 77);
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "unknown data type");
  expect_bad_input([&] { read_volume(good.substr(0, 284 + 95), Format::mgh); }, "truncated");
  b = good;
  bef(b, 82, std::numeric_limits<float>::infinity());
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "c_ras");
  b = good;
  for (std::size_t i = 42; i < 54; ++i) b[i] = 0;  // Mdc row of axis 0 all zero
  expect_bad_input([&] { read_volume(b, Format::mgh); }, "axis 0");
}

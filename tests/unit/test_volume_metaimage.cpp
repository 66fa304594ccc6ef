// MetaImage (.mha) reading and writing: fixtures from tests/data/volume/make_fixtures.py,
// LPS <-> RAS conversion, and malformed headers.
#include <functional>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/gzip.hpp"
#include "formats/volume/volume_io.hpp"
#include "expect_error.hpp"
#include "testdata.hpp"
#include "volume_fixtures.hpp"

using fest::ScalarType;
using fest::Volume;
using fest::formats::Format;
using fest::formats::read_volume;
using fest::formats::write_volume;

namespace {

using fest::test::expect_bad_input;

Volume mha(const std::string& text) { return read_volume(text, Format::mha); }

// A 2x2x1 MET_UCHAR image with the given extra header lines and data 1 2 3 4.
std::string u8_image(const std::string& extra, const std::string& data_file = "LOCAL") {
  return "ObjectType = Image\nNDims = 3\nDimSize = 2 2 1\nElementType = MET_UCHAR\n" + extra +
         "ElementDataFile = " + data_file + "\n" + std::string("\x01\x02\x03\x04", 4);
}

}  // namespace

TEST(VolumeMetaImage, BigEndianFixtureWithTransformMatrix) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/msb_short.mha")), Format::mha);
  fest::test::expect_formula_int16_fixture(v);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 0.25, 2.0}));
  // LPS offset (1,2,3) is RAS (-1,-2,3); LPS axis0 +y -> RAS -y, axis1 -x -> RAS +x.
  EXPECT_EQ(v.origin, (std::array<double, 3>{-1, -2, 3}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{0, 1, 0, -1, 0, 0, 0, 0, 1}));
}

TEST(VolumeMetaImage, ZlibCompressedFloatFixtureWithCrlf) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/zlib_float.mha")), Format::mha);
  EXPECT_EQ(v.type, ScalarType::f32);
  for (std::size_t z = 0; z < 2; ++z)
    for (std::size_t y = 0; y < 3; ++y)
      for (std::size_t x = 0; x < 4; ++x) EXPECT_EQ(v.at(x, y, z), 0.5 * double(x + 4 * y + 12 * z));
  // No geometry stated: unit spacing, zero origin, and the LPS identity is RAS diag(-1,-1,1).
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, -1, 0, 0, 0, 1}));
}

TEST(VolumeMetaImage, TwoDimensionalAndAliases) {
  const Volume v = mha("ObjectType = Image\nNDims = 2\nDimSize = 2 2\nElementType = MET_UCHAR\n"
                       "ElementSpacing = 0.5 0.25\nPosition = 1 2\nOrientation = 1 0 0 1\n"
                       "ElementDataFile = LOCAL\n" + std::string("\x01\x02\x03\x04", 4));
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{2, 2, 1}));
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 0.25, 1}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{-1, -2, 0}));
}

TEST(VolumeMetaImage, AnatomicalOrientationWhenNoMatrix) {
  // ITK letters name where each axis comes from: "LPS" runs x to R, y to A, z to I in LPS.
  const Volume v = mha(u8_image("AnatomicalOrientation = LPS\n"));
  EXPECT_EQ(v.direction, (std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, -1}));
}

TEST(VolumeMetaImage, AsciiData) {
  const Volume v = mha("ObjectType = Image\nNDims = 3\nDimSize = 2 2 1\nBinaryData = False\nElementType = MET_FLOAT\n"
                       "ElementDataFile = LOCAL\n1.5 -2\n3e2 4\n");
  EXPECT_EQ(v.voxels, (std::vector<double>{1.5, -2, 300, 4}));
}

TEST(VolumeMetaImage, RoundTripKeepsGeometryExactlyAllTypes) {
  for (ScalarType t : {ScalarType::u8, ScalarType::i8, ScalarType::u16, ScalarType::i16, ScalarType::u32,
                       ScalarType::i32, ScalarType::u64, ScalarType::i64, ScalarType::f32, ScalarType::f64}) {
    Volume v;
    v.resize(3, 4, 2);
    v.type = t;
    for (std::size_t i = 0; i < v.size(); ++i) v.voxels[i] = static_cast<double>(i * 5 + 2);
    v.spacing = {0.3, 0.7, 1.1};
    v.origin = {-1.0 / 3.0, 2.5, 7.0};
    const double c = 0.6, s = 0.8;  // oblique: rotation about z by atan(4/3)
    v.direction = {c, -s, 0, s, c, 0, 0, 0, 1};
    for (bool compress : {false, true}) {
      const std::string bytes = write_volume(v, Format::mha, {compress, std::nullopt});
      const Volume back = mha(bytes);
      EXPECT_EQ(back.type, t);
      EXPECT_EQ(back.voxels, v.voxels);
      EXPECT_EQ(back.spacing, v.spacing);
      EXPECT_EQ(back.origin, v.origin);
      EXPECT_EQ(back.direction, v.direction);
    }
  }
}

TEST(VolumeMetaImage, WriterStatesLpsOrientation) {
  Volume v;
  v.resize(2, 2, 2);
  const std::string bytes = write_volume(v, Format::mha);
  // RAS identity is LPS diag(-1,-1,1): axis 0 comes from L, axis 1 from P, axis 2 from I.
  EXPECT_NE(bytes.find("AnatomicalOrientation = LPI\n"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("TransformMatrix = -1 0 0 0 -1 0 0 0 1\n"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("ElementDataFile = LOCAL\n"), std::string::npos);
}

// ---- malformed input ----

TEST(VolumeMetaImageMalformed, EmptyAndNoDataFileLine) {
  expect_bad_input([] { mha(""); }, "empty");
  expect_bad_input([] { mha("ObjectType = Image\nNDims = 3\n"); }, "ElementDataFile");
  expect_bad_input([] { mha("ObjectType = Image\nthis is not a key value line\n"); }, "Key = Value");
}

TEST(VolumeMetaImageMalformed, DataFileElsewhere) {
  expect_bad_input([] { mha(u8_image("", "image.raw")); }, "separate file");
  expect_bad_input([] { mha(u8_image("", "LIST")); }, "separate file");
}

TEST(VolumeMetaImageMalformed, DimSizeOverflowAndMismatch) {
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("2 2 1"), 5, "4294967296 4294967296 4294967296")); },
                   "limit");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("2 2 1"), 5, "99999999999999999999999 1 1")); },
                   "range");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("2 2 1"), 5, "2 2")); }, "DimSize");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("2 2 1"), 5, "2 -2 1")); }, "negative");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("2 2 1"), 5, "1000 1000 1000")); }, "truncated");
}

TEST(VolumeMetaImageMalformed, BadFields) {
  expect_bad_input([] { mha(u8_image("").replace(0, 18, "ObjectType = Mesh")); }, "ObjectType");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("MET_UCHAR"), 9, "MET_STRING")); }, "ElementType");
  expect_bad_input([] { mha(u8_image("").replace(u8_image("").find("NDims = 3"), 9, "NDims = 4")); }, "NDims");
  expect_bad_input([] { mha(u8_image("ElementNumberOfChannels = 3\n")); }, "Channels");
  expect_bad_input([] { mha(u8_image("ElementSpacing = 1 0 1\n")); }, "ElementSpacing");
  expect_bad_input([] { mha(u8_image("ElementSpacing = 1 1\n")); }, "ElementSpacing");
  expect_bad_input([] { mha(u8_image("Offset = 1 x 1\n")); }, "Offset");
  expect_bad_input([] { mha(u8_image("TransformMatrix = 1 0 0 0 1 0 0 0\n")); }, "TransformMatrix");
  expect_bad_input([] { mha(u8_image("TransformMatrix = 1 0 0 0 0 0 0 0 1\n")); }, "axis 1");
  expect_bad_input([] { mha(u8_image("ElementByteOrderMSB = maybe\n")); }, "True nor False");
  const std::string no_ndims = "ObjectType = Image\nDimSize = 2 2 1\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n1234";
  expect_bad_input([&] { mha(no_ndims); }, "NDims");
}

TEST(VolumeMetaImageMalformed, CompressedDataCorruptOrLying) {
  const std::string payload = fest::formats::gzip(std::string("\x01\x02\x03\x04", 4), 6, true);
  const std::string head = "ObjectType = Image\nNDims = 3\nDimSize = 2 2 1\nElementType = MET_UCHAR\nCompressedData = True\n";
  EXPECT_EQ(mha(head + "ElementDataFile = LOCAL\n" + payload).voxels, (std::vector<double>{1, 2, 3, 4}));
  expect_bad_input([&] { mha(head + "ElementDataFile = LOCAL\n" + payload.substr(0, 5)); }, "compressed");
  expect_bad_input([&] { mha(head + "ElementDataFile = LOCAL\nxxxxxxxxxxxx"); }, "compressed");
  expect_bad_input([&] { mha(head + "CompressedDataSize = 999\nElementDataFile = LOCAL\n" + payload); }, "CompressedDataSize");
}

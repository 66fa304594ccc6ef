// NIfTI-1 reading and writing: fixtures from tests/data/volume/make_fixtures.py (whose
// docstring states each file's formula and geometry), real MRI volumes, and every
// malformed header the reader must refuse.
#include <cmath>
#include <cstring>
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

Volume small_volume() {
  Volume v;
  v.resize(5, 4, 3);
  v.type = ScalarType::i16;
  for (std::size_t i = 0; i < v.size(); ++i) v.voxels[i] = static_cast<double>(i) * 7.0 - 100.0;
  v.spacing = {0.5, 1.25, 3.0};
  v.origin = {-12.5, 40.0, 7.25};
  return v;
}

std::string nifti_bytes() { return write_volume(small_volume(), Format::nifti); }

void put_i16(std::string& b, std::size_t off, std::int16_t v) { std::memcpy(&b[off], &v, 2); }
void put_i32(std::string& b, std::size_t off, std::int32_t v) { std::memcpy(&b[off], &v, 4); }
void put_f32(std::string& b, std::size_t off, float v) { std::memcpy(&b[off], &v, 4); }

}  // namespace

TEST(VolumeNifti, BigEndianFixtureHasFormulaValuesAndSform) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/be_int16.nii")), Format::nifti);
  fest::test::expect_formula_int16_fixture(v);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1.5, 2.0, 2.5}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{10.0, -20.0, 5.0}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, 1, 0, 0, 0, 1}));
}

TEST(VolumeNifti, SclSlopeAndInterAreApplied) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/scaled_uint8.nii")), Format::nifti);
  ASSERT_EQ(v.size(), 24u);
  for (std::size_t z = 0; z < 2; ++z)
    for (std::size_t y = 0; y < 3; ++y)
      for (std::size_t x = 0; x < 4; ++x) EXPECT_EQ(v.at(x, y, z), 0.5 * double(x + 4 * y + 12 * z) - 10.0);
  // Scaled values are not uint8 any more; they must survive a write unrounded.
  EXPECT_EQ(v.type, ScalarType::f32);
  // No qform or sform: pixdim alone, identity direction, zero origin.
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 0.75, 1.25}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
}

TEST(VolumeNifti, SlopeZeroMeansNoScaling) {
  std::string b = nifti_bytes();
  put_f32(b, 112, 0.0f);
  put_f32(b, 116, 99.0f);
  const Volume v = read_volume(b, Format::nifti);
  EXPECT_EQ(v.voxels, small_volume().voxels);
  EXPECT_EQ(v.type, ScalarType::i16);
}

TEST(VolumeNifti, QformOnlyHeaderGivesRotationAndFlip) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/qform_only.nii")), Format::nifti);
  EXPECT_EQ(v.type, ScalarType::f32);
  EXPECT_EQ(v.at(3, 2, 1), 0.25 * (3 + 8 + 12));
  EXPECT_EQ(v.spacing, (std::array<double, 3>{2, 3, 4}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{10, 20, 30}));
  // 90 degrees about z: axis 0 -> +y, axis 1 -> -x; qfac -1 flips axis 2 -> -z.
  const std::array<double, 9> expected{0, -1, 0, 1, 0, 0, 0, 0, -1};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(v.direction[i], expected[i], 1e-6) << i;
}

TEST(VolumeNifti, SformPreferredOverQform) {
  std::string b = nifti_bytes();
  // Spoil the qform offset: the reader must still use the (intact) sform.
  put_f32(b, 268, 1e6f);
  const Volume v = read_volume(b, Format::nifti);
  EXPECT_EQ(v.origin, small_volume().origin);
  // And with sform_code 0 the qform is used.
  put_i16(b, 254, 0);
  EXPECT_EQ(read_volume(b, Format::nifti).origin[0], 1e6);
}

TEST(VolumeNifti, UnitsMetreAndMicronBecomeMillimetres) {
  std::string b = nifti_bytes();
  b[123] = 1;  // NIFTI_UNITS_METER
  Volume v = read_volume(b, Format::nifti);
  EXPECT_DOUBLE_EQ(v.spacing[0], 500.0);
  EXPECT_DOUBLE_EQ(v.origin[1], 40000.0);
  b[123] = 3;  // NIFTI_UNITS_MICRON
  v = read_volume(b, Format::nifti);
  EXPECT_DOUBLE_EQ(v.spacing[2], 0.003);
}

TEST(VolumeNifti, WriterSetsBothFormsAndStandardOffsets) {
  const std::string b = nifti_bytes();
  ASSERT_EQ(b.size(), 352u + 60u * 2u);
  std::int32_t sizeof_hdr;
  std::memcpy(&sizeof_hdr, b.data(), 4);
  EXPECT_EQ(sizeof_hdr, 348);
  float vox_offset, slope;
  std::memcpy(&vox_offset, &b[108], 4);
  std::memcpy(&slope, &b[112], 4);
  EXPECT_EQ(vox_offset, 352.0f);
  EXPECT_EQ(slope, 1.0f);
  std::int16_t qcode, scode;
  std::memcpy(&qcode, &b[252], 2);
  std::memcpy(&scode, &b[254], 2);
  EXPECT_GT(qcode, 0);
  EXPECT_GT(scode, 0);
  EXPECT_EQ(b.substr(344, 4), std::string("n+1\0", 4));
  // The qform alone describes the same placement as the sform.
  std::string qonly = b;
  put_i16(qonly, 254, 0);
  const Volume q = read_volume(qonly, Format::nifti);
  const Volume s = read_volume(b, Format::nifti);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(q.direction[i], s.direction[i], 1e-6);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(q.origin[i], s.origin[i], 1e-6);
}

TEST(VolumeNifti, ObliqueLeftHandedDirectionSurvivesQform) {
  Volume v = small_volume();
  const double c = std::cos(0.3), s = std::sin(0.3);
  // Rotation about x by 0.3 rad, then a flip of axis 0 (determinant -1).
  v.direction = {-1, 0, 0, 0, c, -s, 0, s, c};
  std::string b = write_volume(v, Format::nifti);
  put_i16(b, 254, 0);  // read back through the quaternion only
  const Volume q = read_volume(b, Format::nifti);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(q.direction[i], v.direction[i], 1e-6) << i;
}

TEST(VolumeNifti, GzippedRoundTripThroughFormatsGzip) {
  const Volume v = small_volume();
  const std::string packed = fest::formats::gzip(write_volume(v, Format::nifti));
  ASSERT_TRUE(fest::formats::is_gzip(packed));
  const Volume back = read_volume(fest::formats::gunzip(packed), Format::nifti);
  EXPECT_EQ(back.dims, v.dims);
  EXPECT_EQ(back.voxels, v.voxels);
  EXPECT_EQ(back.spacing, v.spacing);
  EXPECT_EQ(back.origin, v.origin);
}

TEST(VolumeNifti, FourDWithOneVolumeIsRead) {
  std::string b = nifti_bytes();
  put_i16(b, 40, 4);
  put_i16(b, 48, 1);
  EXPECT_EQ(read_volume(b, Format::nifti).voxels, small_volume().voxels);
  EXPECT_EQ(read_volume(b, Format::nifti).frames, 1u);
  // Two frames need twice the data: the header alone is "truncated", with the data a series.
  put_i16(b, 48, 2);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "truncated");
  b += b.substr(352);
  const Volume v = read_volume(b, Format::nifti);
  EXPECT_EQ(v.frames, 2u);
  EXPECT_EQ(v.dims, small_volume().dims);
  EXPECT_EQ(v.frame(1).voxels, small_volume().voxels);
  // dim[5..7] > 1 (components per voxel) stays refused, by name.
  put_i16(b, 40, 5);
  put_i16(b, 50, 3);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "5-D");
}

TEST(VolumeNifti, TwoDimensionalFileHasOneSlice) {
  std::string b = nifti_bytes();
  put_i16(b, 40, 2);  // dim[3] is ignored beyond dim[0]
  const Volume v = read_volume(b, Format::nifti);
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{5, 4, 1}));
}

TEST(VolumeNifti, RealT1HeadMatchesItsDocumentedShape) {
  FEST_REQUIRE_TESTDATA(path, "mri/t1_head.nii.gz");
  const Volume v = read_volume(fest::formats::gunzip(fest::test::slurp(path)), Format::nifti);
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{128, 128, 62}));
  EXPECT_EQ(v.type, ScalarType::i16);
  EXPECT_DOUBLE_EQ(v.spacing[0], 2.0);
  EXPECT_DOUBLE_EQ(v.spacing[1], 2.0);
  EXPECT_DOUBLE_EQ(v.spacing[2], 3.0);
  double lo = 1e9, hi = -1e9;
  for (double x : v.voxels) lo = std::min(lo, x), hi = std::max(hi, x);
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, 255.0);
  // Round trip through fest's writer keeps every voxel and the placement.
  const Volume back = read_volume(write_volume(v, Format::nifti), Format::nifti);
  EXPECT_EQ(back.voxels, v.voxels);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(back.direction[i], v.direction[i], 1e-7);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back.origin[i], v.origin[i], 1e-4);
}

TEST(VolumeNifti, RealKmeansLabelsAreZeroToSix) {
  FEST_REQUIRE_TESTDATA(path, "mri/t1_kmeans_labels.nii.gz");
  const Volume v = read_volume(fest::formats::gunzip(fest::test::slurp(path)), Format::nifti);
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{128, 128, 62}));
  bool seen[7] = {};
  for (double x : v.voxels) {
    ASSERT_TRUE(x >= 0 && x <= 6 && x == std::floor(x)) << x;
    seen[static_cast<int>(x)] = true;
  }
  for (bool s : seen) EXPECT_TRUE(s);
}

// ---- malformed input ----

TEST(VolumeNiftiMalformed, EmptyAndTruncatedHeader) {
  expect_bad_input([] { read_volume("", Format::nifti); }, "empty");
  const std::string b = nifti_bytes();
  expect_bad_input([&] { read_volume(b.substr(0, 200), Format::nifti); }, "348");
  expect_bad_input([&] { read_volume(b.substr(0, 347), Format::nifti); }, "348");
}

TEST(VolumeNiftiMalformed, WrongMagic) {
  std::string b = nifti_bytes();
  b[345] = 'x';
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "magic");
  // "ni1": the header of a .hdr/.img pair, whose voxels are not in these bytes.
  b.replace(344, 4, std::string("ni1\0", 4));
  expect_bad_input([&] { read_volume(b, Format::nifti); }, ".img file");
}

TEST(VolumeNiftiMalformed, SizeofHdrWrong) {
  std::string b = nifti_bytes();
  put_i32(b, 0, 349);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "sizeof_hdr");
  put_i32(b, 0, 540);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "NIfTI-2");
}

TEST(VolumeNiftiMalformed, DimZeroOrEight) {
  std::string b = nifti_bytes();
  put_i16(b, 40, 0);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "dim[0]");
  put_i16(b, 40, 8);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "dim[0]");
}

TEST(VolumeNiftiMalformed, NegativeAndZeroDims) {
  std::string b = nifti_bytes();
  put_i16(b, 44, -4);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "dim[2]");
  put_i16(b, 44, 0);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "dim[2]");
}

TEST(VolumeNiftiMalformed, HugeDimsNeedMoreBytesThanPresent) {
  std::string b = nifti_bytes();
  put_i16(b, 42, 32767);
  put_i16(b, 44, 32767);
  put_i16(b, 46, 32767);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "truncated");
}

TEST(VolumeNiftiMalformed, VoxOffsetBeyondFileOrInvalid) {
  std::string b = nifti_bytes();
  put_f32(b, 108, 1e9f);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "beyond");
  put_f32(b, 108, 100.0f);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "vox_offset");
  put_f32(b, 108, std::nanf(""));
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "vox_offset");
  put_f32(b, 108, 352.5f);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "vox_offset");
}

TEST(VolumeNiftiMalformed, DataTruncated) {
  const std::string b = nifti_bytes();
  expect_bad_input([&] { read_volume(b.substr(0, b.size() - 1), Format::nifti); }, "truncated");
  expect_bad_input([&] { read_volume(b.substr(0, 352), Format::nifti); }, "truncated");
}

TEST(VolumeNiftiMalformed, UnknownAndUnsupportedDatatypes) {
  std::string b = nifti_bytes();
  put_i16(b, 70, 77);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "unknown datatype");
  put_i16(b, 70, 128);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "RGB24");
  put_i16(b, 70, 32);
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "complex64");
}

TEST(VolumeNiftiMalformed, NonFiniteSform) {
  std::string b = nifti_bytes();
  put_f32(b, 280, std::nanf(""));
  expect_bad_input([&] { read_volume(b, Format::nifti); }, "srow");
}

TEST(VolumeNiftiMalformed, WriterRefusesDimensionsBeyondInt16) {
  Volume v;
  v.resize(40000, 1, 1);
  EXPECT_THROW(write_volume(v, Format::nifti), fest::Error);
}

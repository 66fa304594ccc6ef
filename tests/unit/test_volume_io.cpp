// Across formats: NIfTI -> NRRD -> MetaImage -> NIfTI round trips, type conversion on
// write, describe_volume, and the regression inputs the fuzzer found.
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/volume/volume_io.hpp"
#include "testdata.hpp"

using fest::ScalarType;
using fest::Volume;
using fest::formats::Format;
using fest::formats::read_volume;
using fest::formats::VolumeWriteOptions;
using fest::formats::write_volume;

namespace {

// Geometry chosen so every number is exact in float32 (NIfTI stores float32), with an
// oblique direction: a rotation whose entries are 0.6/0.8 and 0.28/0.96 products.
Volume oblique_volume(ScalarType type) {
  Volume v;
  v.resize(6, 5, 4);
  v.type = type;
  for (std::size_t z = 0; z < 4; ++z)
    for (std::size_t y = 0; y < 5; ++y)
      for (std::size_t x = 0; x < 6; ++x) v.at(x, y, z) = static_cast<double>(x + 6 * y + 30 * z) - 20.0;
  v.spacing = {0.75, 1.5, 2.25};
  v.origin = {-90.5, 126.25, -72.0};
  // Columns: (0.6, 0.8, 0), (-0.8, 0.6, 0), (0, 0, 1) -- a rotation about z.
  v.direction = {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1};
  return v;
}

void expect_same(const Volume& a, const Volume& b, double geometry_tolerance) {
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.voxels, b.voxels);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.spacing[i], b.spacing[i], geometry_tolerance) << "spacing " << i;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.origin[i], b.origin[i], geometry_tolerance) << "origin " << i;
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(a.direction[i], b.direction[i], geometry_tolerance) << "direction " << i;
}

}  // namespace

TEST(VolumeIo, RoundTripNiftiNrrdMhaPreservesEverything) {
  for (ScalarType t : {ScalarType::i16, ScalarType::u8, ScalarType::f32, ScalarType::f64, ScalarType::i64}) {
    Volume start = oblique_volume(t);
    if (t == ScalarType::u8)
      for (double& x : start.voxels) x += 20.0;  // keep uint8 values non-negative
    const Volume from_nifti = read_volume(write_volume(start, Format::nifti), Format::nifti);
    expect_same(start, from_nifti, 1e-6);  // the NIfTI sform is float32
    const Volume from_nrrd = read_volume(write_volume(from_nifti, Format::nrrd), Format::nrrd);
    expect_same(from_nifti, from_nrrd, 1e-12);
    const Volume from_mha = read_volume(write_volume(from_nrrd, Format::mha), Format::mha);
    expect_same(from_nrrd, from_mha, 0.0);
    const Volume back = read_volume(write_volume(from_mha, Format::nifti), Format::nifti);
    expect_same(start, back, 1e-6);
  }
}

TEST(VolumeIo, WorldCoordinatesAgreeAcrossFormats) {
  const Volume v = oblique_volume(ScalarType::i16);
  const auto expected = v.world(5, 4, 3);
  for (Format f : {Format::nifti, Format::nrrd, Format::mha}) {
    const auto w = read_volume(write_volume(v, f), f).world(5, 4, 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(w[i], expected[i], 1e-5) << fest::formats::format_name(f);
  }
}

TEST(VolumeIo, WriteTypeConversionRoundsAndClamps) {
  Volume v;
  v.resize(8, 1, 1);
  v.type = ScalarType::f64;
  v.voxels = {-300.0, -1.5, -0.4, 0.5, 2.5, 254.6, 1e9, std::numeric_limits<double>::quiet_NaN()};
  for (Format f : {Format::nifti, Format::nrrd, Format::mha}) {
    const Volume as_u8 = read_volume(write_volume(v, f, {false, ScalarType::u8}), f);
    EXPECT_EQ(as_u8.type, ScalarType::u8);
    // Nearest integer (halves away from zero), clamped to 0..255, NaN -> 0.
    EXPECT_EQ(as_u8.voxels, (std::vector<double>{0, 0, 0, 1, 3, 255, 255, 0}));
    const Volume as_i8 = read_volume(write_volume(v, f, {false, ScalarType::i8}), f);
    EXPECT_EQ(as_i8.voxels, (std::vector<double>{-128, -2, 0, 1, 3, 127, 127, 0}));
  }
  Volume big;
  big.resize(4, 1, 1);
  big.voxels = {1e30, -1e30, 1e300, -1e300};
  const Volume as_i64 = read_volume(write_volume(big, Format::nrrd, {false, ScalarType::i64}), Format::nrrd);
  EXPECT_EQ(as_i64.voxels[0], 9223372036854775807.0);
  EXPECT_EQ(as_i64.voxels[1], -9223372036854775808.0);
  const Volume as_u64 = read_volume(write_volume(big, Format::mha, {false, ScalarType::u64}), Format::mha);
  EXPECT_EQ(as_u64.voxels[0], 18446744073709551615.0);
  EXPECT_EQ(as_u64.voxels[1], 0.0);
  // float32: beyond its range is +-infinity (IEEE overflow).
  const Volume as_f32 = read_volume(write_volume(big, Format::nifti, {false, ScalarType::f32}), Format::nifti);
  EXPECT_EQ(as_f32.voxels[0], 1e30f);
  EXPECT_EQ(as_f32.voxels[2], std::numeric_limits<double>::infinity());
  EXPECT_EQ(as_f32.voxels[3], -std::numeric_limits<double>::infinity());
}

TEST(VolumeIo, DescribeVolumeStatesShapeAndStatistics) {
  Volume v = oblique_volume(ScalarType::i16);
  const nlohmann::json d = fest::formats::describe_volume(v);
  EXPECT_EQ(d["dimensions"], nlohmann::json({6, 5, 4}));
  EXPECT_EQ(d["spacing"], nlohmann::json({0.75, 1.5, 2.25}));
  EXPECT_EQ(d["origin"], nlohmann::json({-90.5, 126.25, -72.0}));
  EXPECT_EQ(d["direction"].size(), 9u);
  EXPECT_EQ(d["direction"][1], -0.8);
  EXPECT_EQ(d["value_type"], "int16");
  // Values are 0..119 minus 20.
  EXPECT_EQ(d["min"], -20.0);
  EXPECT_EQ(d["max"], 99.0);
  EXPECT_DOUBLE_EQ(d["mean"].get<double>(), 59.5 - 20.0);
}

TEST(VolumeIo, NonVolumeFormatsAreRefused) {
  const std::string nii = write_volume(oblique_volume(ScalarType::u8), Format::nifti);
  EXPECT_THROW(read_volume(nii, Format::ply), fest::Error);
  EXPECT_THROW(write_volume(oblique_volume(ScalarType::u8), Format::png), fest::Error);
}

TEST(VolumeIo, WriterRefusesInconsistentVolume) {
  Volume v;
  v.dims = {2, 2, 2};
  v.voxels.assign(7, 0.0);
  for (Format f : {Format::nifti, Format::nrrd, Format::mha}) EXPECT_THROW(write_volume(v, f), fest::Error);
}

// Every input the fuzzer once crashed on (tests/data/regress/volume/) must now give a
// clean result or a bad_input error in every reader.
TEST(VolumeIo, FuzzRegressionInputs) {
  const std::filesystem::path dir = fest::test::fixture("regress/volume");
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no regression inputs";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string bytes = fest::test::slurp(entry.path().string());
    for (Format f : {Format::nifti, Format::nrrd, Format::mha}) {
      try {
        read_volume(bytes, f);
      } catch (const fest::Error& e) {
        EXPECT_EQ(e.status(), fest::Status::bad_input) << entry.path() << ": " << e.what();
      }
    }
  }
}

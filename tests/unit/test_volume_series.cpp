// 4-D series (Volume::frames), NIfTI-2, .hdr/.img pairs and Analyze 7.5: round trips
// through every format that carries a fourth axis, pair reading from an Input, the SPM
// placement of Analyze headers (formula in formats/volume/nifti.hpp), and the value
// conversions of fconv --type/--rescale.
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/gzip.hpp"
#include "formats/volume/volume_io.hpp"
#include "expect_error.hpp"
#include "testdata.hpp"

using fest::ScalarType;
using fest::Volume;
using fest::formats::Format;
using fest::formats::read_volume;
using fest::formats::VolumeWriteOptions;
using fest::formats::write_volume;
using fest::test::expect_bad_input;

namespace {

// A 4x3x2 grid of 5 frames; value = x + 4y + 12z + 100t - 50, so every frame differs.
// Geometry exact in float32, oblique (a rotation about z by (0.6, 0.8)).
Volume series(ScalarType type = ScalarType::i16, std::size_t frames = 5) {
  Volume v;
  v.resize(4, 3, 2, frames);
  v.type = type;
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t i = 0; i < v.frame_size(); ++i)
      v.voxels[t * v.frame_size() + i] = static_cast<double>(i) + 100.0 * static_cast<double>(t) - 50.0;
  v.spacing = {0.5, 1.25, 3.0};
  v.origin = {-12.5, 40.0, 7.25};
  v.direction = {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1};
  v.frame_spacing = 2.5;
  return v;
}

void expect_same(const Volume& a, const Volume& b, double tol, const char* what) {
  EXPECT_EQ(a.dims, b.dims) << what;
  EXPECT_EQ(a.frames, b.frames) << what;
  EXPECT_EQ(a.voxels, b.voxels) << what;
  EXPECT_NEAR(a.frame_spacing, b.frame_spacing, 1e-6) << what;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.spacing[i], b.spacing[i], tol) << what << " spacing " << i;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.origin[i], b.origin[i], tol * 100) << what << " origin " << i;
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(a.direction[i], b.direction[i], tol) << what << " direction " << i;
}

void put_i16(std::string& b, std::size_t off, std::int16_t v) { std::memcpy(&b[off], &v, 2); }
void put_f32(std::string& b, std::size_t off, float v) { std::memcpy(&b[off], &v, 4); }

}  // namespace

TEST(VolumeSeries, FrameLayoutAndFrameExtraction) {
  const Volume v = series();
  EXPECT_EQ(v.size(), 4u * 3 * 2 * 5);
  EXPECT_EQ(v.voxels.size(), v.size());
  const Volume f3 = v.frame(3);
  EXPECT_EQ(f3.frames, 1u);
  EXPECT_EQ(f3.dims, v.dims);
  EXPECT_EQ(f3.origin, v.origin);
  EXPECT_EQ(f3.at(1, 2, 1), 1 + 4 * 2 + 12 * 1 + 300.0 - 50.0);
  expect_bad_input([&] { v.frame(5); }, "frame 5 does not exist");
  expect_bad_input([&] { v.require_3d("a 3-D tool"); }, "4-D series of 5 frames");
  EXPECT_NO_THROW(f3.require_3d("a 3-D tool"));
}

TEST(VolumeSeries, RoundTripEveryFourDFormat) {
  const Volume start = series();
  for (Format f : {Format::nifti, Format::nifti2, Format::nrrd, Format::mha, Format::mgh}) {
    for (bool compress : {false, true}) {
      const Volume back = read_volume(write_volume(start, f, {compress, std::nullopt}), f);
      // MGH and NIfTI-1 state geometry in float32; the others exactly (NIfTI-2: double).
      const double tol = f == Format::mgh || f == Format::nifti ? 1e-6 : 1e-12;
      expect_same(start, back, tol, fest::formats::format_name(f));
    }
  }
}

TEST(VolumeSeries, ThreeDOutputIsUnchangedByTheFourthAxis) {
  // A 3-D volume writes no fourth axis anywhere: dim[0] 3 in NIfTI, "dimension: 3".
  const Volume v = series(ScalarType::i16, 1);
  const std::string nii = write_volume(v, Format::nifti);
  std::int16_t ndim;
  std::memcpy(&ndim, nii.data() + 40, 2);
  EXPECT_EQ(ndim, 3);
  EXPECT_NE(write_volume(v, Format::nrrd).find("dimension: 3\n"), std::string::npos);
  EXPECT_NE(write_volume(v, Format::mha).find("NDims = 3\n"), std::string::npos);
  const std::string nii4 = write_volume(series(), Format::nifti);
  std::memcpy(&ndim, nii4.data() + 40, 2);
  EXPECT_EQ(ndim, 4);
}

TEST(VolumeSeries, Nifti2HoldsDoublePrecisionGeometry) {
  Volume v = series(ScalarType::f64, 1);
  v.origin = {0.1, -1.0 / 3.0, 1e-9};  // not float32 numbers
  const std::string bytes = write_volume(v, Format::nifti2);
  std::int32_t sizeof_hdr;
  std::memcpy(&sizeof_hdr, bytes.data(), 4);
  EXPECT_EQ(sizeof_hdr, 540);
  EXPECT_EQ(bytes.substr(4, 8), std::string("n+2\0\r\n\032\n", 8));
  const Volume back = read_volume(bytes, Format::nifti2);
  EXPECT_EQ(back.origin, v.origin);
  EXPECT_EQ(back.voxels, v.voxels);
  // The NIfTI-1 writer could not: float32 rounds 0.1.
  EXPECT_NE(read_volume(write_volume(v, Format::nifti), Format::nifti).origin[0], 0.1);
}

TEST(VolumeSeries, PairRoundTripThroughAnInput) {
  const Volume start = series();
  const std::string dir = ::testing::TempDir();
  const std::string hdr = dir + "/fest_pair_test.hdr";
  fest::formats::store_volume(hdr, start, {Format::nifti_pair, false});
  const fest::formats::Input in = fest::formats::load_input(hdr);
  EXPECT_EQ(in.format, Format::nifti_pair);
  EXPECT_TRUE(in.has_companion);
  expect_same(start, fest::formats::parse(in, read_volume), 1e-6, "pair");
  // Named by the image file, the pair is read through its header.
  const fest::formats::Input by_image = fest::formats::load_input(dir + "/fest_pair_test.img");
  EXPECT_EQ(by_image.format, Format::nifti_pair);
  EXPECT_EQ(fest::formats::parse(by_image, read_volume).voxels, start.voxels);
  // The header alone (standard input) says where the voxels are.
  expect_bad_input([&] { read_volume(in.bytes, Format::nifti_pair); }, ".img file");
  // A short image file is "truncated" and named.
  fest::formats::Input cut = in;
  cut.companion.resize(cut.companion.size() - 2);
  expect_bad_input([&] { fest::formats::parse(cut, read_volume); }, "truncated");
  EXPECT_EQ(fest::formats::pair_image_path("a/b.HDR.gz"), "a/b.IMG.gz");
  EXPECT_THROW(fest::formats::pair_image_path("b.nii"), fest::Error);
  EXPECT_THROW(write_volume(start, Format::nifti_pair), fest::Error);
  EXPECT_THROW(write_volume(start, Format::analyze), fest::Error);
}

// An Analyze 7.5 header by hand: SPM's placement world = diag(-dx, dy, dz) (ijk - o),
// o = originator - 1 when set and plausible, else the grid centre (dims - 1) / 2.
TEST(VolumeSeries, AnalyzePlacementFollowsSpm) {
  std::string h(348, '\0');
  const std::int32_t size = 348;
  std::memcpy(h.data(), &size, 4);
  put_i16(h, 40, 3);
  put_i16(h, 42, 5);
  put_i16(h, 44, 4);
  put_i16(h, 46, 3);
  put_i16(h, 70, 2);  // uint8
  put_i16(h, 72, 8);
  put_f32(h, 80, 2.0f);
  put_f32(h, 84, 3.0f);
  put_f32(h, 88, 4.0f);
  std::string img(60, '\0');
  for (int i = 0; i < 60; ++i) img[static_cast<std::size_t>(i)] = static_cast<char>(i);
  fest::formats::Input in;
  in.bytes = h;
  in.format = fest::formats::detect_format(h);
  ASSERT_EQ(in.format, Format::analyze);
  in.has_companion = true;
  in.companion = img;
  Volume v = read_volume(in);
  EXPECT_EQ(v.at(4, 3, 2), 4 + 5 * 3 + 20 * 2);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{2, 3, 4}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, 1, 0, 0, 0, 1}));
  // Centre: o = (2, 1.5, 1); origin = -diag(-2, 3, 4) o.
  EXPECT_EQ(v.origin, (std::array<double, 3>{4, -4.5, -4}));
  // Originator (1-based, int16 at byte 253): voxel (3, 2, 2) -> o = (2, 1, 1).
  put_i16(in.bytes, 253, 3);
  put_i16(in.bytes, 255, 2);
  put_i16(in.bytes, 257, 2);
  v = read_volume(in);
  EXPECT_EQ(v.origin, (std::array<double, 3>{4, -3, -4}));
  // SPM's scale factor (funused1 at byte 112) multiplies the values.
  put_f32(in.bytes, 112, 0.5f);
  EXPECT_EQ(read_volume(in).at(4, 3, 2), 0.5 * (4 + 5 * 3 + 20 * 2));
}

TEST(VolumeSeries, ClippingIsCountedAndRescaleMapsTheRange) {
  Volume v;
  v.resize(5, 1, 1);
  v.voxels = {-300, 0, 100.4, 255.6, std::numeric_limits<double>::quiet_NaN()};
  const auto c = fest::formats::count_clipped(v, ScalarType::u8);
  EXPECT_EQ(c.total, 5u);
  EXPECT_EQ(c.clipped, 2u);  // -300 -> 0 and 255.6 -> 256 -> 255; NaN is not counted
  EXPECT_EQ(fest::formats::count_clipped(v, ScalarType::i16).clipped, 0u);
  EXPECT_EQ(fest::formats::count_clipped(v, ScalarType::f64).clipped, 0u);
  // v' = tmin + (v - lo) (tmax - tmin) / (hi - lo), lo = -300, hi = 255.6.
  ASSERT_TRUE(fest::formats::rescale_to_type(v, ScalarType::u8));
  EXPECT_EQ(v.voxels[0], 0.0);
  EXPECT_EQ(v.voxels[3], 255.0);
  EXPECT_DOUBLE_EQ(v.voxels[1], 300.0 * 255.0 / 555.6);
  EXPECT_TRUE(std::isnan(v.voxels[4]));
  EXPECT_EQ(fest::formats::count_clipped(v, ScalarType::u8).clipped, 0u);
  EXPECT_FALSE(fest::formats::rescale_to_type(v, ScalarType::f32));
  Volume flat;
  flat.resize(2, 1, 1);
  flat.voxels = {7, 7};
  ASSERT_TRUE(fest::formats::rescale_to_type(flat, ScalarType::i8));
  EXPECT_EQ(flat.voxels, (std::vector<double>{-128, -128}));
}

// nibabel's test volumes (scripts/fetch-test-data.sh): the shapes nibabel reports for them
// (img.shape), read here from the bytes alone.
TEST(VolumeSeries, RealNibabelFilesHaveNibabelsShapes) {
  FEST_REQUIRE_TESTDATA(functional, "volumes/nibabel/functional.nii");
  FEST_REQUIRE_TESTDATA(nifti2, "volumes/nibabel/example_nifti2.nii.gz");
  FEST_REQUIRE_TESTDATA(mgz, "volumes/nibabel/test.mgz");
  const Volume f = read_volume(fest::test::slurp(functional), Format::nifti);
  EXPECT_EQ(f.dims, (std::array<std::size_t, 3>{17, 21, 3}));
  EXPECT_EQ(f.frames, 20u);
  const Volume n = read_volume(fest::formats::gunzip(fest::test::slurp(nifti2)), Format::nifti2);
  EXPECT_EQ(n.dims, (std::array<std::size_t, 3>{32, 20, 12}));
  EXPECT_EQ(n.frames, 2u);
  const Volume m = read_volume(fest::formats::gunzip(fest::test::slurp(mgz)), Format::mgh);
  EXPECT_EQ(m.dims, (std::array<std::size_t, 3>{3, 4, 5}));
  EXPECT_EQ(m.frames, 2u);
}

// NRRD reading and writing: fixtures from tests/data/volume/make_fixtures.py, hand-made
// headers for each field, and malformed input.
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

Volume nrrd(const std::string& text) { return read_volume(text, Format::nrrd); }

// A 2x2x1 uint8 volume with the given extra header lines and raw data 1 2 3 4.
std::string raw_u8(const std::string& extra) {
  return "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nencoding: raw\n" + extra + "\n" + std::string("\x01\x02\x03\x04", 4);
}

}  // namespace

TEST(VolumeNrrd, LpsAsciiFixtureIsConvertedToRas) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/lps_ascii.nrrd")), Format::nrrd);
  fest::test::expect_formula_int16_fixture(v);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1.5, 2.0, 2.5}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{10.0, -20.0, 5.0}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{1, 0, 0, 0, -1, 0, 0, 0, 1}));
}

TEST(VolumeNrrd, GzipBigEndianFixtureWithSpacings) {
  const Volume v = read_volume(fest::test::slurp(fest::test::fixture("volume/gzip_uint16.nrrd")), Format::nrrd);
  ASSERT_EQ(v.size(), 24u);
  EXPECT_EQ(v.type, ScalarType::u16);
  for (std::size_t z = 0; z < 2; ++z)
    for (std::size_t y = 0; y < 3; ++y)
      for (std::size_t x = 0; x < 4; ++x) EXPECT_EQ(v.at(x, y, z), 1000.0 + x + 4.0 * y + 12.0 * z);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 0.5, 2.0}));
  EXPECT_EQ(v.direction, (std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
}

TEST(VolumeNrrd, TwoDimensionalImageIsOneSlice) {
  const Volume v = nrrd("NRRD0004\ntype: uint8\ndimension: 2\nsizes: 2 2\nencoding: raw\n"
                        "space: RAS\nspace directions: (0,2,0) (-3,0,0)\nspace origin: (1,2,3)\n\n" +
                        std::string("\x05\x06\x07\x08", 4));
  EXPECT_EQ(v.dims, (std::array<std::size_t, 3>{2, 2, 1}));
  EXPECT_EQ(v.voxels, (std::vector<double>{5, 6, 7, 8}));
  EXPECT_EQ(v.spacing, (std::array<double, 3>{2, 3, 1}));
  // Axis 2 is the normal (0,1,0) x (-1,0,0) = (0,0,1).
  EXPECT_EQ(v.direction, (std::array<double, 9>{0, -1, 0, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(v.origin, (std::array<double, 3>{1, 2, 3}));
}

TEST(VolumeNrrd, SpaceNamesMapToRas) {
  const std::string dirs = "space directions: (1,0,0) (0,1,0) (0,0,1)\nspace origin: (4,5,6)\n";
  for (const char* ras : {"RAS", "right-anterior-superior", "3D-right-handed"}) {
    const Volume v = nrrd(raw_u8(std::string("space: ") + ras + "\n" + dirs));
    EXPECT_EQ(v.origin, (std::array<double, 3>{4, 5, 6})) << ras;
    EXPECT_EQ(v.direction, (std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1})) << ras;
  }
  for (const char* lps : {"LPS", "left-posterior-superior"}) {
    const Volume v = nrrd(raw_u8(std::string("space: ") + lps + "\n" + dirs));
    EXPECT_EQ(v.origin, (std::array<double, 3>{-4, -5, 6})) << lps;
    EXPECT_EQ(v.direction, (std::array<double, 9>{-1, 0, 0, 0, -1, 0, 0, 0, 1})) << lps;
  }
  expect_bad_input([&] { nrrd(raw_u8("space: scanner-xyz-time\n" + dirs)); }, "space");
}

TEST(VolumeNrrd, CrlfHeaderCommentsByteSkipAndKinds) {
  const std::string text = "NRRD0004\r\n# a comment\r\ntype: uchar\r\ndimension: 3\r\nsizes: 2 2 1\r\n"
                           "kinds: space space ???\r\nbyte skip: 3\r\nencoding: raw\r\n\r\n" +
                           std::string("xyz\x01\x02\x03\x04", 7);
  EXPECT_EQ(nrrd(text).voxels, (std::vector<double>{1, 2, 3, 4}));
  // byte skip -1: the data are the last bytes of the file.
  EXPECT_EQ(nrrd(raw_u8("byte skip: -1\n")).voxels, (std::vector<double>{1, 2, 3, 4}));
}

TEST(VolumeNrrd, RoundTripRawAndGzipAllTypes) {
  for (ScalarType t : {ScalarType::u8, ScalarType::i8, ScalarType::u16, ScalarType::i16, ScalarType::u32,
                       ScalarType::i32, ScalarType::u64, ScalarType::i64, ScalarType::f32, ScalarType::f64}) {
    Volume v;
    v.resize(3, 2, 2);
    v.type = t;
    for (std::size_t i = 0; i < v.size(); ++i) v.voxels[i] = static_cast<double>(i * 9 + 1);
    v.spacing = {0.3, 0.7, 1.1};
    v.origin = {-1.0 / 3.0, 2.5, 1e-3};
    for (bool compress : {false, true}) {
      const Volume back = nrrd(write_volume(v, Format::nrrd, {compress, std::nullopt}));
      EXPECT_EQ(back.type, t);
      EXPECT_EQ(back.voxels, v.voxels) << fest::scalar_type_name(t);
      EXPECT_EQ(back.spacing, v.spacing);
      EXPECT_EQ(back.origin, v.origin);
      EXPECT_EQ(back.direction, v.direction);
    }
  }
}

TEST(VolumeNrrd, GzipOutputIsCompressed) {
  Volume v;
  v.resize(32, 32, 32);  // all zeros: compresses to almost nothing
  v.type = ScalarType::f32;
  const std::string plain = write_volume(v, Format::nrrd);
  const std::string packed = write_volume(v, Format::nrrd, {true, std::nullopt});
  EXPECT_NE(packed.find("encoding: gzip"), std::string::npos);
  EXPECT_LT(packed.size(), plain.size() / 10);
}

// ---- malformed input ----

TEST(VolumeNrrdMalformed, WrongMagicAndEmpty) {
  expect_bad_input([] { nrrd(""); }, "empty");
  expect_bad_input([] { nrrd("NRRD00\ntype: uchar\n"); }, "magic");
  expect_bad_input([] { nrrd("NRRDX004\n"); }, "magic");
}

TEST(VolumeNrrdMalformed, MissingRequiredFields) {
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nencoding: raw\n\n1234"); }, "sizes");
  expect_bad_input([] { nrrd("NRRD0004\nsizes: 2 2 1\ndimension: 3\nencoding: raw\n\n1234"); }, "type");
  expect_bad_input([] { nrrd("NRRD0004\nsizes: 2 2 1\ntype: uchar\nencoding: raw\n\n1234"); }, "dimension");
  expect_bad_input([] { nrrd("NRRD0004\nsizes: 2 2 1\ntype: uchar\ndimension: 3\n\n1234"); }, "encoding");
}

TEST(VolumeNrrdMalformed, BadFieldValues) {
  expect_bad_input([] { nrrd("NRRD0004\ntype: block\ndimension: 3\nsizes: 2 2 1\nencoding: raw\n\n1234"); }, "type");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 5\nsizes: 2 2 1 1 1\nencoding: raw\n\n1234"); }, "dimension 5");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2\nencoding: raw\n\n1234"); }, "sizes");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 -2 1\nencoding: raw\n\n1234"); }, "negative");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 0 1\nencoding: raw\n\n1234"); }, "size 0");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 x 1\nencoding: raw\n\n1234"); }, "integer");
  expect_bad_input([] { nrrd(raw_u8("").replace(raw_u8("").find("raw"), 3, "bzip2")); }, "bzip2");
  expect_bad_input([] { nrrd(raw_u8("endian: middle\n")); }, "endian");
  expect_bad_input([] { nrrd(raw_u8("kinds: RGB-color domain domain\n")); }, "RGB-color");
  expect_bad_input([] { nrrd(raw_u8("space: RAS\nspace directions: (1,0,0) (0,0,0) (0,0,1)\n")); }, "axis 1");
  expect_bad_input([] { nrrd(raw_u8("space: RAS\nspace directions: (1,0,0) none (0,0,1)\n")); }, "none");
  expect_bad_input([] { nrrd(raw_u8("space: RAS\nspace directions: (1,0) (0,1,0) (0,0,1)\n")); }, "three");
  expect_bad_input([] { nrrd(raw_u8("space: RAS\nspace origin: (nan,0,0)\n")); }, "origin");
  expect_bad_input([] { nrrd(raw_u8("this line has no colon\n")); }, "field: value");
}

TEST(VolumeNrrdMalformed, HugeSizesAreRefusedBeforeAllocating) {
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n\n1234"); },
                   "limit");
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 99999999999999999999 1 1\nencoding: raw\n\n1"); },
                   "range");
  // Within the voxel limit but far beyond the bytes present.
  expect_bad_input([] { nrrd("NRRD0004\ntype: double\ndimension: 3\nsizes: 1000 1000 1000\nencoding: raw\n\n1234"); },
                   "truncated");
  expect_bad_input([] { nrrd("NRRD0004\ntype: double\ndimension: 3\nsizes: 1000 1000 1000\nencoding: ascii\n\n1 2"); },
                   "truncated");
  expect_bad_input([] { nrrd("NRRD0004\ntype: double\ndimension: 3\nsizes: 1000 1000 1000\nencoding: gzip\n\n" +
                             fest::formats::gzip("12345678")); },
                   "cannot hold");
}

TEST(VolumeNrrdMalformed, DetachedDataFileIsRejected) {
  expect_bad_input([] { nrrd("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nencoding: raw\ndata file: x.raw\n"); },
                   "detached");
}

TEST(VolumeNrrdMalformed, TruncatedRawAndAscii) {
  const std::string ok = raw_u8("");
  expect_bad_input([&] { nrrd(ok.substr(0, ok.size() - 1)); }, "truncated");
  expect_bad_input([] { nrrd("NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 1\nencoding: ascii\n\n1 2 3    "); }, "ends after 3");
  expect_bad_input([] { nrrd("NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 1\nencoding: ascii\n\n1 2 3"); }, "truncated");
  expect_bad_input([] { nrrd("NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 1\nencoding: ascii\n\n1 2 x 4"); }, "not a number");
}

TEST(VolumeNrrdMalformed, GzipDataCorruptOrShort) {
  const std::string head = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: gzip\n\n";
  std::string packed = fest::formats::gzip(std::string(64, '\x07'));
  std::string corrupt = packed;
  for (std::size_t i = 10; i < corrupt.size() - 8; ++i) corrupt[i] = static_cast<char>(corrupt[i] ^ 0x5a);
  expect_bad_input([&] { nrrd(head + corrupt); }, "NRRD gzip");
  expect_bad_input([&] { nrrd(head + packed.substr(0, packed.size() / 2)); }, "NRRD gzip");
  expect_bad_input([&] { nrrd(head + fest::formats::gzip(std::string(63, '\x07'))); }, "NRRD gzip");
  expect_bad_input([&] { nrrd(head + "not gzip at all"); }, "NRRD gzip");
}

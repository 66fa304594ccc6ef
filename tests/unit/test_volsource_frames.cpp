// Frame streams and VTI-free volume input through formats/volume_source.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/error.hpp"
#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"

using namespace fest;

namespace {

// A frame with fields density:1, velocity:3 on 2x2x2 nodes: density = node index,
// velocity = (1, 2, 2) * index (magnitude 3 * index).
std::string frame(int index) {
  std::string h = "NRRD0004\n# fest-frame: index=" + std::to_string(index) +
                  " time=0 fields=density:1,velocity:3\ntype: float\ndimension: 4\nsizes: 4 2 2 2\n"
                  "kinds: list space space space\nspacings: nan 0.5 0.5 0.5\nendian: little\nencoding: raw\n\n";
  for (int p = 0; p < 8; ++p) {
    const float v[4] = {float(p + 10 * index), float(p), float(2 * p), float(2 * p)};
    h.append(reinterpret_cast<const char*>(v), sizeof v);
  }
  return h;
}

}  // namespace

TEST(VolumeSource, FrameStreamFieldsAndFrames) {
  const auto in = formats::recognise(frame(0) + frame(1), "stream");
  formats::VolumeSourceOptions o;
  auto v = formats::read_volume_source(in, o);  // last frame, first field
  EXPECT_EQ(v.dims[0], 2u);
  EXPECT_DOUBLE_EQ(v.spacing[0], 0.5);
  EXPECT_DOUBLE_EQ(v.voxels[3], 13.0);
  o.frame = 0;
  o.field = "velocity";
  v = formats::read_volume_source(in, o);
  EXPECT_DOUBLE_EQ(v.voxels[5], 15.0);  // |(5, 10, 10)|
  o.component = formats::VectorComponent::y;
  v = formats::read_volume_source(in, o);
  EXPECT_DOUBLE_EQ(v.voxels[5], 10.0);
  o.field = "pressure";
  EXPECT_THROW(formats::read_volume_source(in, o), Error);
  o.field = "";
  o.frame = 2;
  EXPECT_THROW(formats::read_volume_source(in, o), Error);
}

TEST(VolumeSource, TruncatedFrameIsBadInput) {
  const std::string s = frame(0);
  try {
    formats::split_frame_stream(s.substr(0, s.size() - 5), "t");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos);
  }
}

TEST(VolumeSource, FramesOfAStreamOneAtATime) {
  const auto in = formats::recognise(frame(0) + frame(1) + frame(2), "stream");
  formats::VolumeSourceOptions o;
  const formats::VolumeFrames frames(in, o);
  ASSERT_EQ(frames.count(), 3u);
  for (std::size_t t = 0; t < 3; ++t) EXPECT_DOUBLE_EQ(frames.frame(t).voxels[3], 3.0 + 10.0 * t);  // density = index + 10 t
}

TEST(VolumeSource, RawLayoutText) {
  const auto L = formats::parse_raw_layout("4,3,2,uint16,big");
  EXPECT_EQ(L.dims[0], 4u);
  EXPECT_EQ(L.dims[2], 2u);
  EXPECT_EQ(L.type, ScalarType::u16);
  EXPECT_TRUE(L.big_endian);
  EXPECT_FALSE(formats::parse_raw_layout("4,3,2,float64").big_endian);
  for (const char* bad : {"4,3,2", "4,3,2,int24", "4,3,0,uint8", "4,3,2.5,uint8", "4,3,2,uint8,middle", "4,3,2,uint8,big,x", ""})
    EXPECT_THROW(formats::parse_raw_layout(bad), std::invalid_argument) << bad;
}

TEST(VolumeSource, RawVolumeBothByteOrders) {
  // int16 samples -2, 258 (0x0102), 7, 0x7fff: big-endian bytes written by hand
  const std::string be("\xff\xfe\x01\x02\x00\x07\x7f\xff", 8);
  formats::RawLayout L;
  L.dims = {2, 2, 1};
  L.type = ScalarType::i16;
  L.big_endian = true;
  L.spacing = {0.5, 2, 3};
  const Volume v = formats::read_raw_volume(be, L, "be");
  EXPECT_DOUBLE_EQ(v.voxels[0], -2);
  EXPECT_DOUBLE_EQ(v.voxels[1], 258);
  EXPECT_DOUBLE_EQ(v.voxels[2], 7);
  EXPECT_DOUBLE_EQ(v.voxels[3], 32767);
  EXPECT_DOUBLE_EQ(v.spacing[0], 0.5);
  L.big_endian = false;
  EXPECT_DOUBLE_EQ(formats::read_raw_volume(be, L, "le").voxels[1], 513);  // 0x0201
  try {
    formats::read_raw_volume(be.substr(1), L, "short");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("needs 8 bytes, got 7"), std::string::npos);
  }
}

// fuzz_volume_source: a frame header line "type: " with no word after it once reached
// substr(npos) and escaped as std::out_of_range. Now the frame's type is refused by name.
TEST(VolumeSource, FrameTypeWithoutAWordIsBadInput) {
  const std::string s = "NRRD0004\ntype: \nkinds: domain domain domain\nencoding: ascii\n\n";
  try {
    formats::split_frame_stream(s, "t");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input) << e.what();
  }
}

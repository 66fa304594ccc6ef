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
  o.component = "y";
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

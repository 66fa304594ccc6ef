// The frame stream (man/man5/fest-frame.5): round trip, header, truncation.
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "fluidsim/frame.hpp"

using namespace fest::fluidsim;

namespace {
Frame sample_frame() {
  Frame f;
  f.index = 7;
  f.time = 0.28;
  f.dim = 2;
  f.size = {3, 2, 1};
  f.spacing = 0.25;
  f.fields = {{"density", 1}, {"velocity", 3}};
  for (int i = 0; i < 24; ++i) f.data.push_back(0.5 * i - 3.0);
  return f;
}
}  // namespace

TEST(FluidsimFrame, RoundTripKeepsEveryValue) {
  const Frame f = sample_frame();
  const std::string bytes = encode_frame(f) + encode_frame(f);
  EXPECT_NE(bytes.find("# fest-frame: index=7 time=0.28 fields=density:1,velocity:3\n"), std::string::npos);
  Frame g;
  const std::size_t next = decode_frame(bytes, 0, g, "t", 0);
  EXPECT_EQ(next, bytes.size() / 2);
  EXPECT_EQ(g.index, 7);
  EXPECT_EQ(g.size, f.size);
  EXPECT_EQ(g.channels(), 4);
  EXPECT_EQ(g.data, f.data);  // multiples of 0.5 are exact in float32
  EXPECT_EQ(g.channel_of("velocity"), 1);
}

TEST(FluidsimFrame, TruncatedFramesAreBadInput) {
  const std::string bytes = encode_frame(sample_frame());
  fest::test::expect_bad_input([&] {
    Frame g;
    decode_frame(std::string_view(bytes).substr(0, bytes.size() - 10), 0, g, "stdin", 12);
  }, "truncated NRRD frame: expected 96 bytes, got 86 (stdin, frame 12)");
}

TEST(FluidsimFrame, BlendIsLinear) {
  const Frame a = sample_frame();
  Frame b = a;
  for (double& v : b.data) v += 2.0;
  const Frame m = blend_frames(a, b, 0.25);
  for (std::size_t i = 0; i < a.data.size(); ++i) EXPECT_DOUBLE_EQ(m.data[i], a.data[i] + 0.5);
}

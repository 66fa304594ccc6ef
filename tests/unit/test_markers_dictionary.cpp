// lib/markers/dictionary: the embedded tables, rotations and nearest-code decoding.
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "markers/dictionary.hpp"

using namespace fest::markers;

TEST(MarkersDictionary, FourQuarterTurnsAreTheIdentity) {
  for (const char* name : {"4x4_50", "6x6_250", "7x7_1000", "apriltag_36h11"}) {
    const Dictionary& d = dictionary(name);
    for (std::uint64_t code : d.codes) {
      std::uint64_t r = code;
      for (int k = 0; k < 4; ++k) r = rotate_code_ccw(r, d.bits);
      ASSERT_EQ(r, code) << name;
    }
  }
}

TEST(MarkersDictionary, RotationMovesTheCornerCell) {
  // 3x3 with only cell (0, 0) white: one ccw turn brings it to (n-1, 0).
  const int n = 3;
  const std::uint64_t top_left = 1ull << 8;
  EXPECT_EQ(rotate_code_ccw(top_left, n), 1ull << (8 - 6));
}

TEST(MarkersDictionary, EveryCodeDecodesInEveryRotation) {
  for (const char* name : {"4x4_50", "5x5_100", "apriltag_36h11", "6x6_1000"}) {
    const Dictionary& d = dictionary(name);
    for (std::size_t id = 0; id < d.codes.size(); ++id) {
      std::uint64_t seen = d.codes[id];
      // The image shows the code turned cw k times; decoding turns it back k times ccw.
      for (int k = 0; k < 4; ++k) {
        const Decoded r = decode(d, seen);
        ASSERT_EQ(r.id, static_cast<int>(id)) << name;
        ASSERT_EQ(r.bit_errors, 0);
        ASSERT_EQ(r.rotation, k);
        // cw = three ccw
        for (int j = 0; j < 3; ++j) seen = rotate_code_ccw(seen, d.bits);
      }
    }
  }
}

TEST(MarkersDictionary, DistancesMatchThePublishedFamilies) {
  // AprilTag families are named by their minimum Hamming distance (36h11: 11, 25h9: 9,
  // 16h5: 5), rotations included.
  EXPECT_EQ(dictionary("apriltag_36h11").min_distance, 11);
  EXPECT_EQ(dictionary("apriltag_25h9").min_distance, 9);
  EXPECT_EQ(dictionary("apriltag_16h5").min_distance, 5);
  EXPECT_EQ(dictionary("apriltag_36h11").codes.size(), 587u);
  EXPECT_EQ(dictionary("4x4_50").codes.size(), 50u);
  EXPECT_EQ(dictionary("apriltag_36h11").max_correction, 3);  // floor(0.6 * 5)
}

TEST(MarkersDictionary, CorrectsUpToItsRadiusAndNoMore) {
  const Dictionary& d = dictionary("apriltag_36h11");
  const std::uint64_t c = d.codes[17];
  EXPECT_EQ(decode(d, c ^ 0b1011).id, 17);
  EXPECT_EQ(decode(d, c ^ 0b1011).bit_errors, 3);
  EXPECT_EQ(decode(d, c ^ 0b11011).id, -1);
}

TEST(MarkersDictionary, UnknownNamesAreRefused) {
  fest::test::expect_bad_input([] { dictionary("4x4_51"); }, "unknown marker dictionary '4x4_51'");
  fest::test::expect_bad_input([] { dictionary("8x8_50"); }, "known: 4x4_50");
  fest::test::expect_bad_input([] { dictionary(""); }, "unknown");
}

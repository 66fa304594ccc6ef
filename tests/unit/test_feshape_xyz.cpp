// lib/feshape/xyz_codec: rows with any separator, header and comments, extra columns;
// malformed rows named by line; exact round trip.
#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "feshape/xyz_codec.hpp"

using namespace fest::feshape;

TEST(FeshapeXyz, ReadsRowsInEveryDialect) {
  const auto p = decode_points("# comment\nx,y,z\n1,2,3\n\n4\t5\t6\t0 0 1\r\n-7e-1 +8 9;\n");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(p[2], Eigen::Vector3d(-0.7, 8, 9));
  EXPECT_TRUE(decode_points("").empty());
}

TEST(FeshapeXyz, MalformedRowsAreBadInput) {
  for (const char* bad : {"1 2 3\n1 2\n", "1 2 3\n1 x 3\n", "1 2 nan\n", "1 2 inf\n", "1 2 3\nx y z\n"}) {
    try {
      decode_points(bad);
      FAIL() << bad;
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input);
      EXPECT_NE(std::string(e.what()).find("line"), std::string::npos);
    }
  }
}

TEST(FeshapeXyz, RoundTripIsExact) {
  const std::vector<Eigen::Vector3d> p{{0.1, -1e-300, 3.141592653589793}, {1e17, 2.5, -0.30000000000000004}};
  EXPECT_EQ(decode_points(encode_points(p)), p);
}

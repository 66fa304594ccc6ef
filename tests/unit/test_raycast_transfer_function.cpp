// Transfer functions: parsing, the opacity correction identity, exact pre-integration
// integrals against numeric quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "raycast/transfer_function.hpp"

using namespace fest::raycast;

TEST(RaycastTransferFunction, ParsesCsvAndPercent) {
  const auto p = parse_transfer_function("value,r,g,b,a\n0%,0,0,0,0\n# c\n50%,1,0.5,0,0.2\n150,1,1,1,1\n", 0, 200, OpacityMode::opacity);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[1].value, 100);
  EXPECT_THROW(parse_transfer_function("0,0,0,0,0\n150,1,1,1,1\n50%,1,1,1,1\n", 0, 200, OpacityMode::opacity), std::invalid_argument);
}

TEST(RaycastTransferFunction, RefusesBadFunctions) {
  EXPECT_THROW(parse_transfer_function("1,0,0,0,0\n0,1,1,1,1\n", 0, 1, OpacityMode::opacity), std::invalid_argument);  // decreasing
  EXPECT_THROW(parse_transfer_function("0,0,0,0,0\n1,1,1,1,1.5\n", 0, 1, OpacityMode::opacity), std::invalid_argument);  // alpha > 1
  EXPECT_NO_THROW(parse_transfer_function("0,0,0,0,0\n1,1,1,1,1.5\n", 0, 1, OpacityMode::extinction));
  EXPECT_THROW(parse_transfer_function("0,0,0,0,0\n", 0, 1, OpacityMode::opacity), std::invalid_argument);  // < 2 points
  EXPECT_THROW(parse_transfer_function("0,0,0,0\n1,1,1,1\n", 0, 1, OpacityMode::opacity), std::invalid_argument);
  EXPECT_THROW(parse_transfer_function("{\"x\": 1}", 0, 1, OpacityMode::opacity), std::invalid_argument);
  EXPECT_THROW(parse_transfer_function("{nope", 0, 1, OpacityMode::opacity), std::invalid_argument);
}

TEST(RaycastTransferFunction, ParaViewJson) {
  const auto p = parse_transfer_function(R"([{"RGBPoints":[0,0,0,1, 10,1,0,0],"Points":[0,0,0.5,0, 10,0.5,0.5,0]}])", 0, 10,
                                         OpacityMode::opacity);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[1].a, 0.5);
  EXPECT_DOUBLE_EQ(p[0].b, 1);
}

// Two segments of ds/2 compose to one of ds exactly in the tau form.
TEST(RaycastTransferFunction, OpacityCorrectionComposes) {
  const TransferFunction tf({{0, 1, 1, 1, 0.3}, {1, 1, 1, 1, 0.3}}, 0, 1, OpacityMode::opacity, 1.0);
  const double tau = tf.at(0.5).tau;
  const double a1 = 1 - std::exp(-tau * 1.0), ah = 1 - std::exp(-tau * 0.5);
  EXPECT_NEAR(a1, 0.3, 1e-12);
  EXPECT_NEAR(1 - (1 - ah) * (1 - ah), a1, 1e-12);
}

TEST(RaycastTransferFunction, IntegralsMatchQuadrature) {
  const TransferFunction tf({{-1, 0, 0, 0, 0}, {0.2, 1, 0.2, 0, 0.5}, {0.25, 0.3, 1, 0.1, 2.0}, {2, 1, 1, 1, 0.1}}, -1, 2,
                            OpacityMode::extinction, 1.0);
  for (double a : {-1.0, -0.3, 0.21, 0.9}) {
    for (double b : {-0.2, 0.24, 1.7, 2.0}) {
      const int N = 200000;
      double T = 0, K[3] = {0, 0, 0};
      for (int k = 0; k < N; ++k) {
        const double v = a + (b - a) * (k + 0.5) / N;
        const auto s = tf.at(v);
        T += s.tau * (b - a) / N;
        for (int c = 0; c < 3; ++c) K[c] += s.tau * s.rgb[c] * (b - a) / N;
      }
      EXPECT_NEAR(tf.integral_tau(b) - tf.integral_tau(a), T, 1e-6);
      const auto kb = tf.integral_tau_color(b), ka = tf.integral_tau_color(a);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(kb[c] - ka[c], K[c], 1e-6);
    }
  }
  EXPECT_TRUE(tf.transparent(-1, -1));
  EXPECT_FALSE(tf.transparent(-1, -0.99));
  EXPECT_FALSE(tf.transparent(-1, 0.5));
}

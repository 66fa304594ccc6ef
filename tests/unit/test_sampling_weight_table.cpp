// Weight tables (docs/resample.md "Weights"): centre convention, normalisation, and the
// four edge modes.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "sampling/weight_table.hpp"

using fest::sampling::EdgeMode;
using fest::sampling::make_kernel;
using fest::sampling::make_weight_table;
using fest::sampling::WeightTable;

namespace {
double weight_of(const WeightTable& t, int o, int index) {
  double w = 0;
  for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < t.offset[static_cast<std::size_t>(o) + 1]; ++j)
    if (t.index[j] == index) w += t.weight[j];
  return w;
}
double sum_of(const WeightTable& t, int o) {
  double s = 0;
  for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < t.offset[static_cast<std::size_t>(o) + 1]; ++j) s += t.weight[j];
  return s;
}
}  // namespace

TEST(SamplingWeightTable, HalvingWithTentHasNoHalfPixelShift) {
  // 8 → 4: output o is centred on input coordinate 2o + 0.5 (between samples 2o and 2o+1);
  // the tent stretched ×2 gives weights 1/8, 3/8, 3/8, 1/8 on 2o−1 .. 2o+2.
  const auto t = make_weight_table(8, 4, make_kernel("triangle"));
  EXPECT_NEAR(weight_of(t, 1, 1), 1.0 / 8, 1e-7);
  EXPECT_NEAR(weight_of(t, 1, 2), 3.0 / 8, 1e-7);
  EXPECT_NEAR(weight_of(t, 1, 3), 3.0 / 8, 1e-7);
  EXPECT_NEAR(weight_of(t, 1, 4), 1.0 / 8, 1e-7);
  // Clamp folds the outside tap into sample 0: 1/8 + 3/8.
  EXPECT_NEAR(weight_of(t, 0, 0), 0.5, 1e-7);
}

TEST(SamplingWeightTable, MagnificationInterpolates) {
  // 4 → 8 with the tent: output 3 is centred on (3.5)/2 − 0.5 = 1.25 → 0.75·x1 + 0.25·x2.
  const auto t = make_weight_table(4, 8, make_kernel("tent"));
  EXPECT_NEAR(weight_of(t, 3, 1), 0.75, 1e-7);
  EXPECT_NEAR(weight_of(t, 3, 2), 0.25, 1e-7);
}

TEST(SamplingWeightTable, EdgeModes) {
  // 5 samples, shift −1.25 moves output 0 to u = −1.25: tent taps at n = −1 (weight 0.75)
  // and n = −2 (0.25), both outside.
  const auto k = make_kernel("tent");
  const auto clamp = make_weight_table(5, 5, k, -1.25, EdgeMode::clamp);
  EXPECT_NEAR(weight_of(clamp, 0, 0), 1.0, 1e-7);
  const auto reflect = make_weight_table(5, 5, k, -1.25, EdgeMode::reflect);  // −1 → 1, −2 → 2
  EXPECT_NEAR(weight_of(reflect, 0, 1), 0.75, 1e-7);
  EXPECT_NEAR(weight_of(reflect, 0, 2), 0.25, 1e-7);
  const auto wrap = make_weight_table(5, 5, k, -1.25, EdgeMode::wrap);  // −1 → 4, −2 → 3
  EXPECT_NEAR(weight_of(wrap, 0, 4), 0.75, 1e-7);
  EXPECT_NEAR(weight_of(wrap, 0, 3), 0.25, 1e-7);
  const auto zero = make_weight_table(5, 5, k, -1.25, EdgeMode::zero);  // nothing left, not renormalised
  EXPECT_EQ(sum_of(zero, 0), 0.0);
  const auto zero_half = make_weight_table(5, 5, k, -0.5, EdgeMode::zero);  // u = −0.5: half outside
  EXPECT_NEAR(sum_of(zero_half, 0), 0.5, 1e-7);
  // Reflect on a one-sample axis maps everything to sample 0.
  EXPECT_NEAR(weight_of(make_weight_table(1, 3, make_kernel("lanczos3"), 0, EdgeMode::reflect), 1, 0), 1.0, 1e-6);
}

TEST(SamplingWeightTable, WeightsSumToOne) {
  for (const char* name : {"box", "mitchell", "lanczos3", "gaussian", "kaiser"})
    for (auto [a, b] : {std::pair{100, 7}, std::pair{7, 100}, std::pair{33, 32}}) {
      const auto t = make_weight_table(a, b, make_kernel(name), 0.3);
      for (int o = 0; o < b; ++o) EXPECT_NEAR(sum_of(t, o), 1.0, 1e-6) << name << " " << a << "->" << b;
    }
}

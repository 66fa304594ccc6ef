// Kernel catalogue (docs/resample.md "Kernels and their responses"): closed-form values, partition of unity,
// frequency responses against the kernel table of docs/resample.md "Figures reproduced" (Z1 table columns K(0.25), K(0.5)),
// and lookup errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "sampling/frequency_response.hpp"
#include "sampling/kernel.hpp"

using fest::sampling::frequency_response;
using fest::sampling::make_kernel;
using fest::sampling::numerical_response;

namespace {
const double pi = std::acos(-1.0);

void expect_usage(const std::string& spec, const std::string& needle) {
  try {
    make_kernel(spec);
    ADD_FAILURE() << "no error for '" << spec << "'";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(SamplingKernels, Lanczos3ClosedForm) {
  const auto k = make_kernel("lanczos3");
  EXPECT_EQ(k.radius, 3.0);
  // sinc(1/4) sinc(1/12) with sin(π/4) = √2/2 and sin(π/12) = (√6 − √2)/4.
  const double s4 = (std::sqrt(2.0) / 2) / (pi / 4), s12 = ((std::sqrt(6.0) - std::sqrt(2.0)) / 4) / (pi / 12);
  EXPECT_NEAR(k(0.25), s4 * s12, 1e-14);
  // sinc(1/2) sinc(1/6) = (2/π)(3/π) = 6/π².
  EXPECT_NEAR(k(0.5), 6 / (pi * pi), 1e-14);
  EXPECT_EQ(k(0.0), 1.0);
  EXPECT_EQ(k(3.0), 0.0);
  EXPECT_EQ(k(-3.5), 0.0);
  EXPECT_NEAR(k(1.0), 0.0, 1e-15);
  EXPECT_NEAR(k(-2.0), 0.0, 1e-15);
}

TEST(SamplingKernels, MitchellClosedForm) {
  const auto k = make_kernel("mitchell");
  // Mitchell–Netravali with B = C = 1/3: k(0) = (6 − 2B)/6 = 8/9, k(1) = B/6 = 1/18, k(2) = 0.
  EXPECT_NEAR(k(0.0), 8.0 / 9, 1e-15);
  EXPECT_NEAR(k(1.0), 1.0 / 18, 1e-15);
  EXPECT_NEAR(k(-1.0), 1.0 / 18, 1e-15);
  EXPECT_NEAR(k(2.0), 0.0, 1e-15);
  // Fractions are accepted as the literature writes them.
  const auto m = make_kernel("mitchell:b=1/3,c=1/3");
  EXPECT_EQ(m(0.7), k(0.7));
  // catrom = (B, C) = (0, 1/2): k(0) = 1, k(1) = 0; bspline (1, 0): k(0) = 2/3, k(1) = 1/6.
  const auto cr = make_kernel("catrom"), bs = make_kernel("bspline");
  EXPECT_NEAR(cr(0.0), 1.0, 1e-15);
  EXPECT_NEAR(cr(1.0), 0.0, 1e-15);
  EXPECT_NEAR(bs(0.0), 2.0 / 3, 1e-15);
  EXPECT_NEAR(bs(1.0), 1.0 / 6, 1e-15);
  // Catmull–Rom at 1/2: (1.5·1/8 − 2.5·1/4 + 1) = 0.5625.
  EXPECT_NEAR(cr(0.5), 0.5625, 1e-15);
}

TEST(SamplingKernels, SimpleShapes) {
  const auto box = make_kernel("box"), tent = make_kernel("tent"), tri = make_kernel("triangle");
  EXPECT_EQ(box(-0.5), 1.0);  // half-open [-0.5, 0.5)
  EXPECT_EQ(box(0.5), 0.0);
  EXPECT_EQ(tent(0.25), 0.75);
  EXPECT_EQ(tri(-0.75), 0.25);
  EXPECT_EQ(tent.name, "triangle");
  const auto g = make_kernel("gaussian:sigma=0.5");
  EXPECT_NEAR(g.radius, 1.5, 1e-15);
  EXPECT_NEAR(g(0.5), std::exp(-0.5), 1e-15);
  EXPECT_EQ(g(1.5), 0.0);
  // Blackman–Harris (width 3) at the centre is a0 + a1 + a2 + a3 = 1.
  EXPECT_NEAR(make_kernel("blackman-harris")(0.0), 1.0, 1e-12);
  EXPECT_NEAR(make_kernel("kaiser")(0.0), 1.0, 1e-12);
  EXPECT_NEAR(make_kernel("kaiser")(2.0), 0.0, 1e-15);
}

TEST(SamplingKernels, InterpolatingKernelsVanishAtNonzeroIntegers) {
  for (const char* name : {"box", "triangle", "catrom", "lanczos2", "lanczos3", "kaiser"}) {
    const auto k = make_kernel(name);
    EXPECT_TRUE(k.interpolating) << name;
    EXPECT_NEAR(k(0.0), 1.0, 1e-15) << name;
    for (int n = 1; n <= 4; ++n) {
      EXPECT_NEAR(k(n), 0.0, 1e-15) << name << " at " << n;
      EXPECT_NEAR(k(-n), 0.0, 1e-15) << name << " at " << -n;
    }
  }
  EXPECT_FALSE(make_kernel("mitchell").interpolating);
  EXPECT_FALSE(make_kernel("bspline").interpolating);
}

TEST(SamplingKernels, PartitionOfUnity) {
  // Box, tent and every Mitchell–Netravali cubic reproduce constants: Σ_n k(x − n) = 1.
  for (const char* name : {"box", "triangle", "catrom", "bspline", "mitchell", "mitchell:b=0.2,c=0.7"}) {
    const auto k = make_kernel(name);
    for (double x : {0.0, 0.1, 0.25, 0.5, 0.77}) {
      double sum = 0;
      for (int n = -4; n <= 4; ++n) sum += k(x - n);
      EXPECT_NEAR(sum, 1.0, 1e-14) << name << " at " << x;
    }
  }
}

TEST(SamplingKernels, ClosedFormResponses) {
  // Box: sinc; tent: sinc²; B-spline: sinc⁴; Gaussian spot: exp(−2π²σ²f²).
  const double s = std::sin(pi / 4) / (pi / 4);
  EXPECT_NEAR(frequency_response(make_kernel("box"), 0.25), s, 1e-15);
  EXPECT_NEAR(frequency_response(make_kernel("tent"), 0.25), s * s, 1e-15);
  EXPECT_NEAR(frequency_response(make_kernel("bspline"), 0.25), s * s * s * s, 1e-15);
  EXPECT_NEAR(frequency_response(make_kernel("gaussian"), 0.25), std::exp(-2 * pi * pi * 0.25 * 0.0625), 1e-15);
  EXPECT_EQ(frequency_response(make_kernel("ideal"), 0.49), 1.0);
  EXPECT_EQ(frequency_response(make_kernel("sinc"), 0.51), 0.0);
  // Simpson agrees with the closed forms where the kernel is smooth enough.
  EXPECT_NEAR(numerical_response(make_kernel("tent"), 0.25), s * s, 1e-8);
  EXPECT_NEAR(numerical_response(make_kernel("bspline"), 0.25), s * s * s * s, 1e-8);
}

TEST(SamplingKernels, ResponsesMatchSpecTable) {
  // docs/resample.md "Figures reproduced", zone-plate table: K(0.25) and K(0.5) of the (truncated) resize kernels,
  // printed to 4 decimals.
  struct Row {
    const char* name;
    double k025, k05;
  };
  for (const Row& r : {Row{"triangle", 0.8106, 0.4053}, Row{"gaussian:sigma=0.5", 0.7388, 0.2910},
                       Row{"bspline", 0.6570, 0.1643}, Row{"mitchell", 0.8450, 0.3833},
                       Row{"catrom", 0.9390, 0.4928}, Row{"lanczos2", 0.9407, 0.4958},
                       Row{"lanczos3", 1.0114, 0.5017}, Row{"blackman-harris:width=3", 0.8066, 0.4128}}) {
    const auto k = make_kernel(r.name);
    EXPECT_NEAR(numerical_response(k, 0.25), r.k025, 1e-4) << r.name;
    EXPECT_NEAR(numerical_response(k, 0.5), r.k05, 1e-4) << r.name;
  }
  // The box's row comes from its closed form: sinc(0.25) = 0.9003, sinc(0.5) = 2/π = 0.6366.
  EXPECT_NEAR(frequency_response(make_kernel("box"), 0.5), 2 / pi, 1e-15);
}

TEST(SamplingKernels, DualBoxIsBox) {
  const auto d = make_kernel("dual:box");
  EXPECT_EQ(d.name, "dual:box");
  EXPECT_EQ(d(0.3), 1.0);
  EXPECT_NEAR(frequency_response(d, 0.3), frequency_response(make_kernel("box"), 0.3), 1e-15);
  const auto dt = make_kernel("dual:tent");
  EXPECT_TRUE(std::isinf(dt.radius));
  // P_opt(0) = R(0) / Σ_k R(k)² = 1 for any interpolating-at-DC display.
  EXPECT_NEAR(frequency_response(dt, 0.0), 1.0, 1e-12);
  // Tent: A_r(f) = Σ_k sinc⁴(f + k) = (2 + cos 2πf)/3 (DTFT of {1/6, 4/6, 1/6}).
  const double f = 0.3, s = std::sin(pi * f) / (pi * f);
  EXPECT_NEAR(frequency_response(dt, f), s * s / ((2 + std::cos(2 * pi * f)) / 3), 1e-9);
}

TEST(SamplingKernels, UnknownNamesAndBadParameters) {
  expect_usage("no-such-kernel", "lanczos");  // the message lists the known names
  expect_usage("lanczos:a=0", "out of range");
  expect_usage("lanczos:a=-1", "out of range");
  expect_usage("lanczos:q=2", "no parameter 'q'");
  expect_usage("gaussian:sigma=abc", "not a finite number");
  expect_usage("gaussian:sigma=1/0", "not a finite number");
  expect_usage("mitchell:b", "key=value");
  expect_usage("box:a=1", "no parameters");
  expect_usage("dual", "reconstruction kernel");
  expect_usage("dual:point", "finite reconstruction");
  expect_usage("kaiser:beta=1000", "beta");
  EXPECT_EQ(make_kernel("lanczos:a=2").name, "lanczos:a=2");
  EXPECT_EQ(make_kernel("lanczos2").radius, 2.0);
}

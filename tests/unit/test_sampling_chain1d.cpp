// 1-D sampling chain (docs/resample.md "The 1-D chain and the optimal prefilter"): Fig. 10.10 (C1), the ideal low-pass
// (C2), the non-linear edge reconstruction of Fig. 10.2 (C3), the derived chain table of
// §3, and the orthogonal-projection claim of §10.5 (C6).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "sampling/chain1d.hpp"

using fest::sampling::analyse_chain;
using fest::sampling::edge_experiment;
using fest::sampling::make_kernel;

TEST(SamplingChain1d, Fig1010BoxPrefilterBoxDisplay) {
  // C1: f = 2.75 f_N = 1.375 f_S, p = r = box of width 1; targets ±1e-5.
  const auto box = make_kernel("box");
  const auto c = analyse_chain(box, box, 1.375);
  EXPECT_NEAR(c.prefilter, -0.21388, 1e-5);
  EXPECT_NEAR(c.amplitude_at(1), -0.16772, 1e-5);  // alias at f − 1 = 0.375
  EXPECT_NEAR(c.amplitude_at(2), -0.10063, 1e-5);  // alias at f − 2 = −0.625
  EXPECT_NEAR(c.survived, 0.045743, 1e-5);
  EXPECT_NEAR(c.alias_rms, 0.208918, 1e-5);
  EXPECT_NEAR(c.mse, 0.954253, 1e-5);
  // Mathematics: Σ_k sinc²(f − k) = 1, so with all terms MSE = (1 − P²)² + P²(1 − P²).
  const double p2 = c.prefilter * c.prefilter;
  EXPECT_NEAR(c.mse, (1 - p2) * (1 - p2) + p2 * (1 - p2), 1e-5);
  EXPECT_LT(c.mse, 1.0);  // better than the ideal low-pass (C2)
}

TEST(SamplingChain1d, IdealLowPassRemovesTheSignal) {
  // C2: above Nyquist the ideal prefilter leaves nothing: A_0 = 0, MSE = 1.
  const auto c = analyse_chain(make_kernel("ideal"), make_kernel("box"), 1.375);
  EXPECT_EQ(c.survived, 0.0);
  EXPECT_EQ(c.alias_rms, 0.0);
  EXPECT_EQ(c.mse, 1.0);
}

TEST(SamplingChain1d, DerivedChainTable) {
  // docs/resample.md "Figures reproduced", derived chain table, ±1e-4: MSE for the dual, box, ideal and p = r prefilters.
  struct Row {
    const char* display;
    double f, dual, box, ideal, same;
  };
  for (const Row& r : {Row{"box", 0.25, 0.1894, 0.1894, 0.1993, 0.1894},
                       Row{"box", 0.40, 0.4272, 0.4272, 0.4863, 0.4272},
                       Row{"tent", 0.10, 0.0002, 0.0025, 0.0013, 0.0043},
                       Row{"tent", 0.25, 0.0145, 0.0808, 0.0455, 0.1240},
                       Row{"tent", 0.40, 0.1736, 0.3604, 0.2514, 0.4741},
                       Row{"gaussian:sigma=0.5", 0.25, 0.0071, 0.1178, 0.0743, 0.2140},
                       Row{"bspline", 0.25, 0.0002, 0.1669, 0.1177, 0.3230},
                       Row{"tent", 1.375, 0.9951, 1.0393, 1.0000, 0.9967}}) {
    const auto disp = make_kernel(r.display);
    const auto dual = make_kernel(std::string("dual:") + r.display);
    SCOPED_TRACE(std::string(r.display) + " f=" + std::to_string(r.f));
    EXPECT_NEAR(analyse_chain(dual, disp, r.f).mse, r.dual, 1e-4);
    EXPECT_NEAR(analyse_chain(make_kernel("box"), disp, r.f).mse, r.box, 1e-4);
    EXPECT_NEAR(analyse_chain(make_kernel("ideal"), disp, r.f).mse, r.ideal, 1e-4);
    EXPECT_NEAR(analyse_chain(disp, disp, r.f).mse, r.same, 1e-4);
  }
}

TEST(SamplingChain1d, DualPrefilterMinimisesTheError) {
  // C6 generalised: the dual prefilter is the orthogonal projection, so no other prefilter
  // in the catalogue does better for the same display, at any frequency.
  for (const char* display : {"box", "tent", "bspline"}) {
    const auto r = make_kernel(display);
    const auto dual = make_kernel(std::string("dual:") + display);
    for (double f : {0.05, 0.2, 0.35, 0.45, 0.7, 1.375}) {
      const double best = analyse_chain(dual, r, f, 400).mse;
      for (const char* p : {"box", "tent", "ideal", "gaussian", "bspline", "point"})
        EXPECT_LE(best, analyse_chain(make_kernel(p), r, f, 400).mse + 1e-12) << display << " " << p << " f=" << f;
    }
  }
}

TEST(SamplingChain1d, EdgeRecoveredExactly) {
  // C3: an isolated step at any x0 is recovered exactly (abs error < 1e-12).
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const double x0 = u(rng);
    const auto e = edge_experiment(x0);
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0], x0, 1e-12);
  }
  EXPECT_NEAR(edge_experiment(-3.3)[0], -3.3, 1e-12);
}

TEST(SamplingChain1d, CloseEdgesAreDisplaced) {
  // C3: bar [0.2, 1.7] → [2/7, 1.625]: samples 0.4, 0.75, 0.35 at n = 0, 1, 2.
  const auto e = edge_experiment(0.2, 1.7);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0], 2.0 / 7, 1e-9);
  EXPECT_NEAR(e[1], 1.625, 1e-9);
}

TEST(SamplingChain1d, BadArguments) {
  const auto box = make_kernel("box");
  EXPECT_THROW(analyse_chain(box, box, NAN), fest::Error);
  EXPECT_THROW(analyse_chain(box, box, 0.3, 0), fest::Error);
  EXPECT_THROW(edge_experiment(1.0, 0.5), fest::Error);
}

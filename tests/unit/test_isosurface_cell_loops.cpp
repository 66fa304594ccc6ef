// Loop construction on all 256 cube cases (docs/isosurf.md "Loop construction").
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "isosurface/cell_loops.hpp"

using namespace fest::isosurface;

TEST(CellLoops, EveryCrossedEdgeOnceInOneSimpleLoop) {
  for (int c = 0; c < 256; ++c) {
    const int amb = ambiguous_faces(c);
    for (int d = 0; d < 64; ++d) {
      if (d & ~amb) continue;
      std::set<int> seen;
      for (const auto& loop : build_loops(c, d)) {
        EXPECT_GE(loop.size(), 3u);
        for (int e : loop) EXPECT_TRUE(seen.insert(e).second) << "case " << c;
      }
      std::set<int> crossed;
      for (int e = 0; e < 12; ++e) {
        const auto& info = edge_info(e);
        if ((c >> info.corner & 1) != (c >> (info.corner | 1 << info.axis) & 1)) crossed.insert(e);
      }
      EXPECT_EQ(seen, crossed) << "case " << c;
    }
  }
}

// The single-corner case: loop through the x, y, z edges at the origin has normal
// along (1,1,1), i.e. from the inside corner outwards (along -grad f).
TEST(CellLoops, OrientationOfOneInsideCorner) {
  const auto loops = build_loops(1, 0);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 3u);
  auto mid = [](int e) {
    const auto& info = edge_info(e);
    std::array<double, 3> p{double(info.corner & 1), double(info.corner >> 1 & 1), double(info.corner >> 2 & 1)};
    p[info.axis] = 0.5;
    return p;
  };
  const auto a = mid(loops[0][0]), b = mid(loops[0][1]), c = mid(loops[0][2]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  EXPECT_GT(n[0], 0);
  EXPECT_NEAR(n[0], n[1], 1e-12);
  EXPECT_NEAR(n[0], n[2], 1e-12);
}

// Every loop's (Newell) normal points away from the inside corners: the sum over inside
// corners of (corner - loop centroid) . normal is negative -- a coarse but case-wide check.
TEST(CellLoops, LoopsFaceAwayFromInside) {
  for (int c = 1; c < 255; ++c) {
    if (__builtin_popcount(c) != 1 && __builtin_popcount(c) != 7) continue;
    for (const auto& loop : build_loops(c, 0)) {
      double n[3] = {0, 0, 0}, m[3] = {0, 0, 0};
      std::vector<std::array<double, 3>> p;
      for (int e : loop) {
        const auto& info = edge_info(e);
        std::array<double, 3> q{double(info.corner & 1), double(info.corner >> 1 & 1), double(info.corner >> 2 & 1)};
        q[info.axis] = 0.5;
        p.push_back(q);
      }
      for (std::size_t k = 0; k < p.size(); ++k) {
        const auto& a = p[k];
        const auto& b = p[(k + 1) % p.size()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
        for (int i = 0; i < 3; ++i) m[i] += a[i] / p.size();
      }
      double s = 0;
      for (int v = 0; v < 8; ++v)
        if (c >> v & 1) s += (double(v & 1) - m[0]) * n[0] + (double(v >> 1 & 1) - m[1]) * n[1] + (double(v >> 2 & 1) - m[2]) * n[2];
      EXPECT_LT(s, 0) << "case " << c;
    }
  }
}

// Asymptotic decider against brute-force connectivity of the bilinear interpolant's inside
// set on a fine grid (test plan item 1).
TEST(CellLoops, DeciderMatchesBilinearConnectivity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.01, 1.0);
  int tested = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // inside diagonal q0,q2 (g >= 0), outside q1,q3
    const double g0 = U(rng), g2 = U(rng), g1 = -U(rng), g3 = -U(rng);
    const int N = 300;
    // flood fill inside set from corner (0,0)
    std::vector<int> lab(N * N, 0);
    auto val = [&](int x, int y) {
      const double u = (x + 0.5) / N, v = (y + 0.5) / N;
      return g0 * (1 - u) * (1 - v) + g1 * u * (1 - v) + g2 * u * v + g3 * (1 - u) * v;
    };
    std::vector<int> stack{0};
    lab[0] = 1;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % N, y = p / N;
      const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (auto& d : nb) {
        const int a = x + d[0], b = y + d[1];
        if (a < 0 || b < 0 || a >= N || b >= N || lab[a + N * b] || val(a, b) < 0) continue;
        lab[a + N * b] = 1;
        stack.push_back(a + N * b);
      }
    }
    const bool connected = lab[(N - 1) + N * (N - 1)] == 1;
    // skip near-ties where the grid cannot resolve the saddle
    const double saddle = (g0 * g2 - g1 * g3) / (g0 + g2 - g1 - g3);
    if (std::abs(saddle) < 0.02) continue;
    EXPECT_EQ(inside_connected(g0, g1, g2, g3), connected) << g0 << " " << g1 << " " << g2 << " " << g3;
    ++tested;
  }
  EXPECT_GT(tested, 30);
}

// Min-max pyramid against brute force on odd sizes (docs/isosurf.md "Min-max octree").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "volume_pyramid/minmax_pyramid.hpp"

using namespace fest::volume_pyramid;

TEST(MinMaxPyramid, EqualsBruteForce) {
  for (auto dims : {std::array<std::size_t, 3>{5, 7, 9}, std::array<std::size_t, 3>{33, 33, 33}, std::array<std::size_t, 3>{18, 9, 41}}) {
    ScalarGrid g;
    g.dims = dims;
    g.values.resize(g.size());
    std::uint32_t s = 99;
    for (auto& v : g.values) v = static_cast<float>((s = s * 1103515245u + 12345u) >> 8);
    const MinMaxPyramid p(g, 2);
    for (int l = p.finest_level(); l <= p.root_level(); ++l) {
      const auto n = p.nodes(l);
      const std::size_t w = std::size_t{1} << l;
      for (std::size_t k = 0; k < n[2]; ++k)
        for (std::size_t j = 0; j < n[1]; ++j)
          for (std::size_t i = 0; i < n[0]; ++i) {
            float lo = INFINITY, hi = -INFINITY;
            for (std::size_t z = k * w; z <= std::min((k + 1) * w, dims[2] - 1); ++z)
              for (std::size_t y = j * w; y <= std::min((j + 1) * w, dims[1] - 1); ++y)
                for (std::size_t x = i * w; x <= std::min((i + 1) * w, dims[0] - 1); ++x) {
                  lo = std::min(lo, g.at(x, y, z));
                  hi = std::max(hi, g.at(x, y, z));
                }
            ASSERT_EQ(p.min(l, i, j, k), lo);
            ASSERT_EQ(p.max(l, i, j, k), hi);
          }
    }
    EXPECT_EQ(p.nodes(p.root_level()), (std::array<std::size_t, 3>{1, 1, 1}));
  }
}

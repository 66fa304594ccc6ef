// Lifting transforms: exact inversion of the integer wavelets for every line length,
// the 9/7's near-orthonormal scaling, and the 3-D pyramid round trip.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "wavelet/lifting.hpp"

using namespace fest::wavelet;

TEST(WaveletLifting, IntegerLinesInvertExactly) {
  std::mt19937_64 rng(7);
  for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
    for (std::size_t n = 1; n < 40; ++n) {
      std::vector<std::int64_t> x(n), y, scratch(n);
      for (auto& v : x) v = static_cast<std::int64_t>(rng() % 200001) - 100000;
      y = x;
      forward_line(y.data(), n, w, scratch.data());
      inverse_line(y.data(), n, w, scratch.data());
      EXPECT_EQ(x, y) << wavelet_name(w) << " n=" << n;
    }
  }
}

TEST(WaveletLifting, Cdf53PredictsLinearRampsExactly) {
  // The 5/3 predictor is linear interpolation, so a ramp has zero interior details.
  std::vector<std::int64_t> x(32), scratch(32);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 3 * static_cast<std::int64_t>(i) + 5;
  forward_line(x.data(), x.size(), Wavelet::cdf53, scratch.data());
  for (std::size_t i = 16; i < 31; ++i) EXPECT_EQ(x[i], 0) << i;
}

TEST(WaveletLifting, Cdf97IsNearlyOrthonormal) {
  // A constant line goes to the low band with gain sqrt(2) per sample pair; energy of a
  // random line is kept within a few percent (biorthogonal, not exactly orthogonal).
  std::vector<double> c(64, 1.0), scratch(64);
  forward_line_97(c.data(), c.size(), scratch.data());
  for (std::size_t i = 2; i < 30; ++i) EXPECT_NEAR(c[i], std::sqrt(2.0), 1e-9);
  for (std::size_t i = 34; i < 62; ++i) EXPECT_NEAR(c[i], 0.0, 1e-9);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  std::vector<double> x(256);
  double e0 = 0, e1 = 0;
  for (auto& v : x) {
    v = g(rng);
    e0 += v * v;
  }
  std::vector<double> y = x, s2(256);
  forward_line_97(y.data(), y.size(), s2.data());
  for (double v : y) e1 += v * v;
  EXPECT_NEAR(e1 / e0, 1.0, 0.1);
  inverse_line_97(y.data(), y.size(), s2.data());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], y[i], 1e-12);
}

TEST(WaveletLifting, Pyramid3dRoundTrips) {
  const Dims dims{13, 7, 9};
  const std::size_t n = dims[0] * dims[1] * dims[2];
  std::mt19937_64 rng(11);
  std::vector<std::int64_t> x(n);
  for (auto& v : x) v = static_cast<std::int64_t>(rng() % 4096);
  for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
    for (int threads : {1, 3}) {
      std::vector<std::int64_t> y = x;
      forward_3d(y, dims, 3, w, threads);
      inverse_3d(y, dims, 3, w, threads);
      EXPECT_EQ(x, y);
    }
  }
  std::vector<double> d(x.begin(), x.end()), e = d;
  forward_3d(e, dims, 3, 2);
  inverse_3d(e, dims, 3, 2);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(d[i], e[i], 1e-9);
}

TEST(WaveletLifting, SubbandsTileThePyramid) {
  const Dims dims{13, 7, 1};
  const int levels = default_levels(dims);
  std::vector<int> hits(13 * 7, 0);
  for (const auto& b : subbands(dims, levels))
    for (std::size_t z = b.lo[2]; z < b.hi[2]; ++z)
      for (std::size_t y = b.lo[1]; y < b.hi[1]; ++y)
        for (std::size_t x = b.lo[0]; x < b.hi[0]; ++x) ++hits[x + 13 * y];
  for (int h : hits) EXPECT_EQ(h, 1);
}

// The 3-D inverse by definition: inverse_line on every line, axis z, then y, then x, of
// every level from the coarsest. inverse_3d works on blocks of lines at once (and on
// blocks of 256 x at a time along y and z); on arbitrary coefficients (not only those
// of a forward transform) it must give exactly the same integers, for any thread count.
namespace {

std::vector<std::int64_t> inverse_by_lines(std::vector<std::int64_t> data, const Dims& dims, int levels, Wavelet w) {
  const std::size_t stride[3] = {1, dims[0], dims[0] * dims[1]};
  for (int l = levels - 1; l >= 0; --l) {
    const Dims c = level_dims(dims, l);
    for (int a = 2; a >= 0; --a) {
      const std::size_t n = c[static_cast<std::size_t>(a)];
      std::vector<std::int64_t> line(n), scratch(n);
      for (std::size_t z = 0; z < (a == 2 ? 1 : c[2]); ++z)
        for (std::size_t y = 0; y < (a == 1 ? 1 : c[1]); ++y)
          for (std::size_t x = 0; x < (a == 0 ? 1 : c[0]); ++x) {
            const std::size_t base = x + y * stride[1] + z * stride[2];
            for (std::size_t k = 0; k < n; ++k) line[k] = data[base + k * stride[a]];
            inverse_line(line.data(), n, w, scratch.data());
            for (std::size_t k = 0; k < n; ++k) data[base + k * stride[a]] = line[k];
          }
    }
  }
  return data;
}

}  // namespace

TEST(WaveletLifting, Inverse3dMatchesLineByLineDefinition) {
  std::mt19937_64 rng(23);
  for (const Dims dims : {Dims{300, 5, 7}, Dims{6, 9, 300}, Dims{17, 1, 12}, Dims{2, 3, 2}}) {
    const std::size_t n = dims[0] * dims[1] * dims[2];
    std::vector<std::int64_t> x(n);
    for (auto& v : x) v = static_cast<std::int64_t>(rng() % 200001) - 100000;
    for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
      const std::vector<std::int64_t> want = inverse_by_lines(x, dims, 3, w);
      for (int threads : {1, 2, 5}) {
        std::vector<std::int64_t> y = x;
        inverse_3d(y, dims, 3, w, threads);
        EXPECT_EQ(want, y) << wavelet_name(w) << " " << dims[0] << "x" << dims[1] << "x" << dims[2] << " threads " << threads;
      }
    }
  }
}

// The same without row lists (the encoder's reconstructions), on pyramids whose rows are
// zero in a coarse level's cube but not past it: a pass that finds a row zero inside the
// cube must not skip the row's finer details (a first version of the sparse inverse did:
// the encoder then stored thousands of voxels as outliers, the plume's file grew 1.8x).
TEST(WaveletLifting, Inverse3dOfSparseRowsMatchesLineByLineDefinition) {
  std::mt19937_64 rng(31);
  for (const Dims dims : {Dims{66, 66, 66}, Dims{37, 30, 20}, Dims{65, 64, 63}})
    for (const int levels : {2, 4})
      for (int pattern = 0; pattern < 2; ++pattern) {
        const std::size_t n = dims[0] * dims[1] * dims[2];
        std::vector<std::int64_t> x(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
          const std::size_t px = i % dims[0], row = i / dims[0];
          // every fifth row; or only the finest level's part of every third row
          const bool on = pattern == 0 ? row % 5 == 0 : (row % 3 == 0 && px >= (dims[0] + 1) / 2);
          if (on) x[i] = static_cast<std::int64_t>(rng() % 2001) - 1000;
        }
        for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
          const std::vector<std::int64_t> want = inverse_by_lines(x, dims, levels, w);
          for (int threads : {1, 2}) {
            std::vector<std::int64_t> y = x;
            inverse_3d(y, dims, levels, w, threads);
            EXPECT_EQ(want, y) << wavelet_name(w) << " " << dims[0] << "x" << dims[1] << "x" << dims[2] << " levels "
                               << levels << " pattern " << pattern << " threads " << threads;
          }
        }
      }
}

// The inverse transform told which rows hold non-zero coefficients (docs/volwave.md §4)
// skips the rows it can prove zero; the result must be the line-by-line definition's,
// also where the non-zeros are a few sparse blobs, single samples at band edges (the
// lifting's reach at the boundaries) or negative (the AVX2 floor division), and the row
// spans it returns must cover every non-zero of the result.
TEST(WaveletLifting, Inverse3dWithRowListsMatchesLineByLineDefinition) {
  std::mt19937_64 rng(29);
  for (const Dims dims : {Dims{66, 66, 66}, Dims{300, 5, 7}, Dims{6, 9, 300}, Dims{17, 1, 12}, Dims{33, 17, 2},
                          Dims{1, 9, 12}, Dims{2, 3, 5}, Dims{41, 3, 3}})
    for (const int levels : {0, 1, 3}) {
      const std::size_t n = dims[0] * dims[1] * dims[2];
      for (int trial = 0; trial < 4; ++trial) {
        std::vector<std::int64_t> x(n, 0);
        // A few non-zero coefficients anywhere in the pyramid (trial 0: the corners and
        // last samples of every axis too).
        const std::size_t count = trial == 0 ? 3 : trial == 3 ? n / 3 : 1 + rng() % 40;  // trial 3: dense
        for (std::size_t k = 0; k < count; ++k) x[rng() % n] = static_cast<std::int64_t>(rng() % 2001) - 1000;
        if (trial == 0) x[0] = -7, x[n - 1] = 5, x[dims[0] - 1] = -3;
        // Rows listed per level as the decoder lists them: a non-zero's row goes to the
        // level of its band, the coarsest level whose cube holds the coefficient.
        std::vector<RowList> rows(static_cast<std::size_t>(levels) + 1);
        for (std::size_t i = 0; i < n; ++i) {
          if (x[i] == 0) continue;
          const std::size_t px = i % dims[0], py = i / dims[0] % dims[1], pz = i / (dims[0] * dims[1]);
          int level = 0;
          for (int l = levels; l >= 0; --l) {
            const Dims c = level_dims(dims, l);
            if (px < c[0] && py < c[1] && pz < c[2]) {
              level = l;
              break;
            }
          }
          rows[static_cast<std::size_t>(level)].push_back(py + dims[1] * pz);
        }
        for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
          const std::vector<std::int64_t> want = inverse_by_lines(x, dims, levels, w);
          for (int threads : {1, 2}) {
            std::vector<std::int64_t> y = x;
            std::vector<RowSpan> spans;
            inverse_3d(y.data(), dims, levels, w, threads, rows, &spans);
            EXPECT_EQ(want, y) << wavelet_name(w) << " " << dims[0] << "x" << dims[1] << "x" << dims[2] << " levels "
                               << levels << " trial " << trial;
            ASSERT_EQ(spans.size(), dims[1] * dims[2]);
            for (std::size_t r = 0; r < spans.size(); ++r) {
              ASSERT_LE(spans[r].begin, spans[r].end);
              ASSERT_LE(spans[r].end, dims[0]);
              for (std::size_t i = 0; i < dims[0]; ++i) {
                if (i >= spans[r].begin && i < spans[r].end) continue;
                ASSERT_EQ(y[i + dims[0] * r], 0) << "row " << r << " x " << i << " outside its span";
              }
            }
          }
        }
      }
    }
}

// The streamed resize (docs/resample.md, "Streaming"): the ring of rows gives the separable
// sum out(o_y, o_x) = Σ_i wy(o_y, i) Σ_j wx(o_x, j) in(i, j) of the two weight tables,
// checked against that double sum evaluated directly; bounded reads; any thread count
// give the same bytes; declined when a group's first row moves back (wrap edges).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/image.hpp"
#include "sampling/float_image.hpp"
#include "sampling/kernel.hpp"
#include "sampling/resize.hpp"
#include "sampling/streamed_resize.hpp"
#include "sampling/weight_table.hpp"

using namespace fest::sampling;

namespace {

// Stored rows copied out band by band (as a file reader does), recording the reads.
class CountingRows final : public StoredRows {
 public:
  explicit CountingRows(const cv::Mat& m) : m_(m) {}
  int width() const override { return m_.cols; }
  int height() const override { return m_.rows; }
  int type() const override { return m_.type(); }
  cv::Mat rows(int first, int last, void* buffer) const override {
    EXPECT_LE(0, first);
    EXPECT_LT(first, last);
    EXPECT_LE(last, m_.rows);
    rows_read += last - first;
    widest = std::max(widest.load(), last - first);
    const std::size_t row = m_.cols * m_.elemSize();
    for (int y = first; y < last; ++y) std::memcpy(static_cast<char*>(buffer) + (y - first) * row, m_.ptr(y), row);
    return cv::Mat(last - first, m_.cols, m_.type(), buffer);
  }
  mutable std::atomic<long> rows_read{0};
  mutable std::atomic<int> widest{0};

 private:
  const cv::Mat& m_;
};

cv::Mat test_image(int w, int h, int c) {
  cv::Mat m(h, w, CV_MAKETYPE(CV_32F, c));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < c; ++ch)
        m.ptr<float>(y)[x * c + ch] = static_cast<float>(std::sin(0.05 * x * x / w + 0.3 * y + ch) + 0.01 * ch);
  return m;
}

// Σ_i wy Σ_j wx in, in double precision, straight from the tables.
double direct_sum(const cv::Mat& m, const WeightTable& tx, const WeightTable& ty, int ox, int oy, int ch) {
  const int c = m.channels();
  double sum = 0;
  for (std::size_t i = ty.offset[oy]; i < ty.offset[oy + 1]; ++i)
    for (std::size_t j = tx.offset[ox]; j < tx.offset[ox + 1]; ++j)
      sum += double(ty.weight[i]) * tx.weight[j] * m.ptr<float>(ty.index[i])[tx.index[j] * c + ch];
  return sum;
}

}  // namespace

TEST(SamplingStreamedResize, EqualsTheDirectSeparableSum) {
  for (const char* kernel : {"lanczos3", "mitchell"})
    for (EdgeMode edge : {EdgeMode::clamp, EdgeMode::zero, EdgeMode::reflect})
      for (int c : {1, 3})
        for (auto [w, h, ow, oh] : {std::array<int, 4>{211, 157, 23, 19}, {40, 30, 97, 71}, {64, 300, 64, 7}})
          for (bool columns_first : {true, false}) {
            const cv::Mat m = test_image(w, h, c);
            const WeightTable tx = make_weight_table(w, ow, make_kernel(kernel), 0.25, edge);
            const WeightTable ty = make_weight_table(h, oh, make_kernel(kernel), -0.5, edge);
            CountingRows rows(m);
            const auto out = resize_streamed(rows, Encoding{}, StreamedPasses{&tx, &ty, columns_first}, 2);
            ASSERT_TRUE(out.has_value());
            double worst = 0;
            for (int oy = 0; oy < oh; ++oy)
              for (int ox = 0; ox < ow; ++ox)
                for (int ch = 0; ch < c; ++ch)
                  worst = std::max(worst, std::fabs(out->row(oy)[ox * c + ch] - direct_sum(m, tx, ty, ox, oy, ch)));
            // Float sums of ≤ ~60 taps of values ≤ 1.01 with weights summing to 1 (lanczos's
            // |w| sum is < 1.3 per axis): a few float ulps of 1.
            EXPECT_LT(worst, 2e-6) << kernel << " c=" << c << " " << w << "x" << h << " -> " << ow << "x" << oh;
          }
}

TEST(SamplingStreamedResize, ReadsEachRowAboutOnceAndNeverTheWholeImage) {
  const cv::Mat m = test_image(300, 4000, 1);
  const WeightTable tx = make_weight_table(300, 40, make_kernel("lanczos3"));
  const WeightTable ty = make_weight_table(4000, 500, make_kernel("lanczos3"));
  for (int threads : {1, 2}) {
    CountingRows rows(m);
    ASSERT_TRUE(resize_streamed(rows, Encoding{}, StreamedPasses{&tx, &ty, true}, threads).has_value());
    // Each thread re-reads only the rows its first group shares with the previous block.
    EXPECT_LE(rows.rows_read.load(), 4000 + 48 * (threads - 1));
    EXPECT_GE(rows.rows_read.load(), 4000);
    EXPECT_LT(rows.widest.load(), 4000 / 4);
  }
}

TEST(SamplingStreamedResize, SameBytesForAnyThreadCountAndBothOrders) {
  const cv::Mat m = test_image(509, 411, 3);
  const WeightTable tx = make_weight_table(509, 61, make_kernel("lanczos3"));
  const WeightTable ty = make_weight_table(411, 53, make_kernel("lanczos3"));
  for (bool columns_first : {true, false}) {
    const auto one = resize_streamed(MatRows(m), Encoding{}, StreamedPasses{&tx, &ty, columns_first}, 1);
    for (int threads : {2, 3, 7}) {
      const auto many = resize_streamed(MatRows(m), Encoding{}, StreamedPasses{&tx, &ty, columns_first}, threads);
      EXPECT_EQ(one->data, many->data) << threads << " threads";
    }
  }
}

TEST(SamplingStreamedResize, DeclinedWhenTheFirstRowMovesBack) {
  // Wrap edges: the last outputs read the first rows again, which the ring has dropped.
  const cv::Mat m = test_image(50, 50, 1);
  const WeightTable tx = make_weight_table(50, 20, make_kernel("lanczos3"), 0, EdgeMode::wrap);
  const WeightTable ty = make_weight_table(50, 20, make_kernel("lanczos3"), 0, EdgeMode::wrap);
  EXPECT_FALSE(resize_streamed(MatRows(m), Encoding{}, StreamedPasses{&tx, &ty, false}, 1).has_value());
  // resize() then takes the whole-image passes, and gets the direct sum.
  fest::Image img;
  img.color_space = fest::ColorSpace::linear;
  img.pixels = m;
  ResizeOptions o;
  o.kernel = make_kernel("lanczos3");
  o.edge = EdgeMode::wrap;
  const fest::Image out = resize(img, 20, 20, o);
  for (int oy = 0; oy < 20; ++oy)
    for (int ox = 0; ox < 20; ++ox) EXPECT_NEAR(out.pixels.at<float>(oy, ox), direct_sum(m, tx, ty, ox, oy, 0), 2e-6);
}

TEST(SamplingStreamedResize, FloatRangeClampUsesTheWholeInput) {
  // A single bright pixel far from the first rows: the range clamp of an integer output
  // must know the input's maximum, gathered while streaming.
  cv::Mat m(400, 20, CV_32FC1, cv::Scalar(0.25f));
  m.at<float>(350, 10) = 0.75f;
  fest::Image img;
  img.color_space = fest::ColorSpace::linear;
  img.pixels = m;
  ResizeOptions o;
  o.kernel = make_kernel("lanczos3");
  o.clamp = ClampMode::range;
  o.output_depth = CV_32F;
  const fest::Image out = resize(img, 20, 40, o);
  double lo, hi;
  cv::minMaxLoc(out.pixels, &lo, &hi);
  EXPECT_GE(lo, 0.25);
  EXPECT_LE(hi, 0.75);
  EXPECT_GT(hi, 0.25);
}

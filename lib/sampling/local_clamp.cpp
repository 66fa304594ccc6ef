#include "sampling/local_clamp.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fest::sampling {

namespace {

struct Span {
  int lo, hi;  // inclusive input index range
};

// The input samples under the main lobe of each output index: |n − u| ≤ σ, or the two
// neighbours of u when magnifying (σ = 1 then reaches exactly them).
std::vector<Span> lobe_spans(int n_in, int n_out, double shift) {
  const double scale = static_cast<double>(n_out) / n_in;
  const double sigma = std::max(1.0, 1.0 / scale);
  std::vector<Span> spans(static_cast<std::size_t>(n_out));
  for (int o = 0; o < n_out; ++o) {
    const double u = (o + 0.5) / scale - 0.5 + shift;
    int lo = static_cast<int>(std::ceil(u - sigma - 1e-9)), hi = static_cast<int>(std::floor(u + sigma + 1e-9));
    lo = std::clamp(lo, 0, n_in - 1);
    hi = std::clamp(hi, 0, n_in - 1);
    spans[static_cast<std::size_t>(o)] = {std::min(lo, hi), std::max(lo, hi)};
  }
  return spans;
}

// Running min or max over the spans along x, then along y (the window is a rectangle, so
// the two 1-D passes give the 2-D extreme).
template <typename Pick>
FloatImage extreme(const FloatImage& in, const std::vector<Span>& xs, const std::vector<Span>& ys, Pick pick) {
  const int c = in.channels;
  FloatImage rows(static_cast<int>(xs.size()), in.height, c);
  for (int y = 0; y < in.height; ++y)
    for (std::size_t o = 0; o < xs.size(); ++o)
      for (int ch = 0; ch < c; ++ch) {
        float v = in.row(y)[xs[o].lo * c + ch];
        for (int n = xs[o].lo + 1; n <= xs[o].hi; ++n) v = pick(v, in.row(y)[n * c + ch]);
        rows.row(y)[static_cast<int>(o) * c + ch] = v;
      }
  FloatImage out(rows.width, static_cast<int>(ys.size()), c);
  const std::size_t len = static_cast<std::size_t>(rows.width) * static_cast<std::size_t>(c);
  for (std::size_t o = 0; o < ys.size(); ++o) {
    float* dst = out.row(static_cast<int>(o));
    std::copy(rows.row(ys[o].lo), rows.row(ys[o].lo) + len, dst);
    for (int n = ys[o].lo + 1; n <= ys[o].hi; ++n)
      for (std::size_t i = 0; i < len; ++i) dst[i] = pick(dst[i], rows.row(n)[i]);
  }
  return out;
}

}  // namespace

void clamp_to_local_range(const FloatImage& in, double shift_x, double shift_y, FloatImage& out) {
  const auto xs = lobe_spans(in.width, out.width, shift_x);
  const auto ys = lobe_spans(in.height, out.height, shift_y);
  const FloatImage lo = extreme(in, xs, ys, [](float a, float b) { return std::min(a, b); });
  const FloatImage hi = extreme(in, xs, ys, [](float a, float b) { return std::max(a, b); });
  for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = std::clamp(out.data[i], lo.data[i], hi.data[i]);
}

}  // namespace fest::sampling

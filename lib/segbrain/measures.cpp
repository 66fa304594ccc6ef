// Verification measurements.
#include "segbrain/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "segbrain/morphology.hpp"

namespace fest::segbrain {

double deep_intensity(const Grid& g, const Image& img, const Mask& mask, double frac) {
  return deep_intensity(img, mask, depth(g, mask), frac);
}

double deep_intensity(const Image& img, const Mask& mask, const std::vector<double>& d, double frac) {
  std::vector<double> ds;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (mask[i]) ds.push_back(d[i]);
  if (ds.empty()) return std::numeric_limits<double>::quiet_NaN();
  auto k = static_cast<std::size_t>((1.0 - std::clamp(frac, 0.0, 1.0)) * static_cast<double>(ds.size() - 1));
  std::nth_element(ds.begin(), ds.begin() + static_cast<std::ptrdiff_t>(k), ds.end());
  const double cut = ds[k];
  std::vector<float> v;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (mask[i] && d[i] >= cut && std::isfinite(img[i])) v.push_back(img[i]);
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  auto q = static_cast<std::size_t>(0.75 * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(q), v.end());
  return v[q];
}

double skin_contact_fraction(const Grid& g, const Mask& m, const Mask& head, double dist_mm) {
  return skin_contact_fraction(m, depth(g, head), dist_mm);
}

double skin_contact_fraction(const Mask& m, const std::vector<double>& d, double dist_mm) {
  std::size_t n = 0, near = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i]) {
      ++n;
      near += d[i] <= dist_mm;
    }
  return n ? double(near) / double(n) : 0.0;
}

namespace {

// Perimeter (mm) and area (mm²) of one axial slice of a mask: boundary edges between
// in-slice 4-neighbours (the slice border counts as an edge).
std::pair<double, double> slice_shape(const Grid& g, const Mask& m, std::size_t z) {
  double per = 0, area = 0;
  const double sx = g.spacing[0], sy = g.spacing[1];
  for (std::size_t y = 0; y < g.n[1]; ++y)
    for (std::size_t x = 0; x < g.n[0]; ++x) {
      if (!m[g.index(x, y, z)]) continue;
      area += sx * sy;
      if (x == 0 || !m[g.index(x - 1, y, z)]) per += sy;
      if (x + 1 == g.n[0] || !m[g.index(x + 1, y, z)]) per += sy;
      if (y == 0 || !m[g.index(x, y - 1, z)]) per += sx;
      if (y + 1 == g.n[1] || !m[g.index(x, y + 1, z)]) per += sx;
    }
  return {per, area};
}

constexpr double kMinSliceAreaMM2 = 1000.0;  // 10 cm²

}  // namespace

double contour_length_ratio(const Grid& g, const Mask& m, const Mask& head) {
  std::vector<double> r;
  for (std::size_t z = 0; z < g.n[2]; ++z) {
    auto [pm, am] = slice_shape(g, m, z);
    auto [ph, ah] = slice_shape(g, head, z);
    if (am < kMinSliceAreaMM2 || ah <= 0) continue;
    r.push_back((pm / std::sqrt(am)) / (ph / std::sqrt(ah)));
  }
  if (r.empty()) return 0;
  // The median: below the orbits a correct brain section is legitimately ragged
  // (temporal lobes, cerebellum), so one slice must not decide.
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
  return r[r.size() / 2];
}

std::pair<double, double> slice_consistency(const Grid& g, const Mask& m) {
  double change = 0, min_dice = 1;
  const std::size_t plane = g.n[0] * g.n[1];
  const double pix = g.spacing[0] * g.spacing[1];
  for (std::size_t z = 0; z + 1 < g.n[2]; ++z) {
    std::size_t a = 0, b = 0, both = 0;
    for (std::size_t i = 0; i < plane; ++i) {
      bool p = m[z * plane + i], q = m[(z + 1) * plane + i];
      a += p;
      b += q;
      both += p && q;
    }
    if (a * pix < kMinSliceAreaMM2 || b * pix < kMinSliceAreaMM2) continue;
    change = std::max(change, std::fabs(double(a) - double(b)) / double(std::max(a, b)));
    min_dice = std::min(min_dice, 2.0 * double(both) / double(a + b));
  }
  return {change, min_dice};
}

double dice(const Mask& a, const Mask& b) {
  std::size_t na = 0, nb = 0, both = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    na += a[i] != 0;
    nb += b[i] != 0;
    both += a[i] && b[i];
  }
  return na + nb ? 2.0 * double(both) / double(na + nb) : 1.0;
}

}  // namespace fest::segbrain

// Hessian tubularity and Dijkstra line tracking.
#include "segbrain/tracking.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

#include "segbrain/derivatives.hpp"

namespace fest::segbrain {
namespace {

struct Box {
  std::array<std::size_t, 3> lo{0, 0, 0}, hi{0, 0, 0};  // inclusive
  bool empty = true;
};

void include(Box& b, const Grid& g, std::size_t i) {
  const std::array<std::size_t, 3> c{i % g.n[0], (i / g.n[0]) % g.n[1], i / (g.n[0] * g.n[1])};
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = b.empty ? c[a] : std::min(b.lo[a], c[a]);
    b.hi[a] = b.empty ? c[a] : std::max(b.hi[a], c[a]);
  }
  b.empty = false;
}

void grow(Box& b, const Grid& g, double margin_mm) {
  for (int a = 0; a < 3; ++a) {
    const auto m = static_cast<std::size_t>(std::ceil(margin_mm / g.spacing[a]));
    b.lo[a] = b.lo[a] > m ? b.lo[a] - m : 0;
    b.hi[a] = std::min(g.n[a] - 1, b.hi[a] + m);
  }
}

Grid box_grid(const Grid& g, const Box& b) {
  Grid s;
  s.spacing = g.spacing;
  for (int a = 0; a < 3; ++a) s.n[a] = b.hi[a] - b.lo[a] + 1;
  return s;
}

std::size_t to_full(const Grid& g, const Box& b, const Grid& s, std::size_t j) {
  const std::size_t x = j % s.n[0], y = (j / s.n[0]) % s.n[1], z = j / (s.n[0] * s.n[1]);
  return g.index(x + b.lo[0], y + b.lo[1], z + b.lo[2]);
}

// Eigenvalues of a symmetric 3x3 matrix (trigonometric solution), any order.
std::array<double, 3> sym_eigenvalues(double a, double b, double c, double d, double e, double f) {
  // [[a d e] [d b f] [e f c]]
  const double p1 = d * d + e * e + f * f;
  const double q = (a + b + c) / 3;
  if (p1 <= 1e-30 * (a * a + b * b + c * c) || p1 == 0) return {a, b, c};
  const double p2 = (a - q) * (a - q) + (b - q) * (b - q) + (c - q) * (c - q) + 2 * p1;
  const double p = std::sqrt(p2 / 6);
  const double ba = (a - q) / p, bb = (b - q) / p, bc = (c - q) / p, bd = d / p, be = e / p, bf = f / p;
  const double det = ba * (bb * bc - bf * bf) - bd * (bd * bc - bf * be) + be * (bd * bf - bb * be);
  const double r = std::clamp(det / 2, -1.0, 1.0);
  const double phi = std::acos(r) / 3;
  const double e1 = q + 2 * p * std::cos(phi);
  const double e3 = q + 2 * p * std::cos(phi + 2 * M_PI / 3);
  return {e1, 3 * q - e1 - e3, e3};
}

}  // namespace

Image vesselness(const Grid& g, const Image& img, double sigma_mm, Polarity polarity, const Mask& within) {
  Box b;
  if (within.empty()) {
    b.empty = false;
    for (int a = 0; a < 3; ++a) b.hi[a] = g.n[a] - 1;
  } else {
    for (std::size_t i = 0; i < within.size(); ++i)
      if (within[i]) include(b, g, i);
  }
  Image out(g.size(), 0.0f);
  if (b.empty) return out;
  grow(b, g, 3 * sigma_mm + 2 * *std::max_element(g.spacing.begin(), g.spacing.end()));
  const Grid s = box_grid(g, b);
  Image sub(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) sub[j] = img[to_full(g, b, s, j)];

  // Hessian entries, sigma²-normalised so responses compare across scales.
  const bool none[3] = {false, false, false};
  const int orders[6][3] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
  std::array<Image, 6> h;
  for (int k = 0; k < 6; ++k) {
    h[k] = gaussian_derivative(s, sub, sigma_mm, orders[k], none);
    for (float& v : h[k]) v = static_cast<float>(v * sigma_mm * sigma_mm);
  }
  std::vector<std::array<float, 3>> lam(s.size());
  double max_norm = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    auto l = sym_eigenvalues(h[0][j], h[1][j], h[2][j], h[3][j], h[4][j], h[5][j]);
    std::sort(l.begin(), l.end(), [](double x, double y) { return std::abs(x) < std::abs(y); });
    lam[j] = {float(l[0]), float(l[1]), float(l[2])};
    if (within.empty() || within[to_full(g, b, s, j)])
      max_norm = std::max(max_norm, std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]));
  }
  const double c = 0.5 * max_norm, alpha = 0.5, beta = 0.5;
  if (c <= 0) return out;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const std::size_t i = to_full(g, b, s, j);
    if (!within.empty() && !within[i]) continue;
    const double l1 = lam[j][0], l2 = lam[j][1], l3 = lam[j][2];
    // Bright tubes curve down across their axis (l2, l3 < 0), dark tubes up.
    if (l2 == 0 || l3 == 0 || (l2 > 0) != (l3 > 0)) continue;
    if (polarity == Polarity::bright && l3 > 0) continue;
    if (polarity == Polarity::dark && l3 < 0) continue;
    const double ra = std::abs(l2 / l3), rb = std::abs(l1) / std::sqrt(std::abs(l2 * l3));
    const double ss = l1 * l1 + l2 * l2 + l3 * l3;
    out[i] = static_cast<float>((1 - std::exp(-ra * ra / (2 * alpha * alpha))) * std::exp(-rb * rb / (2 * beta * beta)) *
                                (1 - std::exp(-ss / (2 * c * c))));
  }
  return out;
}

std::vector<std::size_t> line_track(const Grid& g, const Image& cost, const Mask& from, const Mask& to, double margin_mm) {
  Box b;
  bool any_from = false, any_to = false;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (from[i]) include(b, g, i), any_from = true;
    if (to[i]) include(b, g, i), any_to = true;
  }
  if (!any_from || !any_to) return {};
  grow(b, g, margin_mm);
  const Grid s = box_grid(g, b);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(s.size(), inf);
  std::vector<std::int64_t> prev(s.size(), -1);
  auto passable = [&](std::size_t i) { return std::isfinite(cost[i]) && cost[i] >= 0; };
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const std::size_t i = to_full(g, b, s, j);
    if (from[i] && passable(i)) {
      dist[j] = 0;
      heap.push({0.0, j});
    }
  }
  // The 26 steps and their lengths in mm.
  struct Step {
    int dx, dy, dz;
    double len;
  };
  std::vector<Step> steps;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dx || dy || dz)
          steps.push_back({dx, dy, dz, std::sqrt(dx * dx * g.spacing[0] * g.spacing[0] + dy * dy * g.spacing[1] * g.spacing[1] +
                                                 dz * dz * g.spacing[2] * g.spacing[2])});
  std::int64_t reached = -1;
  while (!heap.empty()) {
    auto [d, j] = heap.top();
    heap.pop();
    if (d > dist[j]) continue;
    const std::size_t i = to_full(g, b, s, j);
    if (to[i]) {
      reached = static_cast<std::int64_t>(j);
      break;
    }
    const long x = long(j % s.n[0]), y = long((j / s.n[0]) % s.n[1]), z = long(j / (s.n[0] * s.n[1]));
    for (const Step& st : steps) {
      const long nx = x + st.dx, ny = y + st.dy, nz = z + st.dz;
      if (nx < 0 || ny < 0 || nz < 0 || nx >= long(s.n[0]) || ny >= long(s.n[1]) || nz >= long(s.n[2])) continue;
      const std::size_t k = s.index(std::size_t(nx), std::size_t(ny), std::size_t(nz));
      const std::size_t ik = to_full(g, b, s, k);
      if (!passable(ik)) continue;
      const double nd = d + 0.5 * (double(cost[i]) + double(cost[ik])) * st.len;
      if (nd < dist[k]) {
        dist[k] = nd;
        prev[k] = static_cast<std::int64_t>(j);
        heap.push({nd, k});
      }
    }
  }
  std::vector<std::size_t> path;
  for (std::int64_t j = reached; j >= 0; j = prev[std::size_t(j)]) path.push_back(to_full(g, b, s, std::size_t(j)));
  std::reverse(path.begin(), path.end());
  return path;
}

double path_length_mm(const Grid& g, const std::vector<std::size_t>& path, std::size_t stride) {
  double len = 0;
  stride = std::max<std::size_t>(stride, 1);
  for (std::size_t k = 0; k + 1 < path.size(); k += stride) {
    const std::size_t a = path[k], c = path[std::min(k + stride, path.size() - 1)];
    double s2 = 0;
    const double da[3] = {double(a % g.n[0]) - double(c % g.n[0]), double((a / g.n[0]) % g.n[1]) - double((c / g.n[0]) % g.n[1]),
                          double(a / (g.n[0] * g.n[1])) - double(c / (g.n[0] * g.n[1]))};
    for (int ax = 0; ax < 3; ++ax) s2 += da[ax] * g.spacing[ax] * da[ax] * g.spacing[ax];
    len += std::sqrt(s2);
  }
  return len;
}

}  // namespace fest::segbrain

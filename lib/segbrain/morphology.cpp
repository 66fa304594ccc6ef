// Components, EDT, morphology, hole filling, region growing.
#include "segbrain/morphology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fest::segbrain {
namespace {

struct Offset {
  int dx, dy, dz;
};

std::vector<Offset> neighbourhood(int conn) {
  std::vector<Offset> o;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        int k = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (k == 0) continue;
        bool in = conn == 26 || (conn == 18 && k <= 2) || (conn == 6 && k == 1) ||
                  (conn == 8 && dz == 0) || (conn == 4 && dz == 0 && k == 1);
        if (in) o.push_back({dx, dy, dz});
      }
  return o;
}

// Flood fill with an explicit stack (no recursion on big volumes). Interior voxels take
// the precomputed linear offsets without bounds checks; only border voxels check.
template <typename Visit>
void flood(const Grid& g, std::size_t start, const std::vector<Offset>& nb, Visit&& accept) {
  const long nx = static_cast<long>(g.n[0]), ny = static_cast<long>(g.n[1]), nz = static_cast<long>(g.n[2]);
  std::vector<long> lin;
  for (const auto& o : nb) lin.push_back(o.dx + nx * (o.dy + ny * o.dz));
  std::vector<std::size_t> stack{start};
  while (!stack.empty()) {
    std::size_t i = stack.back();
    stack.pop_back();
    const long x = static_cast<long>(i % g.n[0]), yz = static_cast<long>(i / g.n[0]);
    const long y = yz % ny, z = yz / ny;
    const bool interior = x > 0 && y > 0 && z > 0 && x + 1 < nx && y + 1 < ny && z + 1 < nz;
    for (std::size_t k = 0; k < nb.size(); ++k) {
      if (!interior) {
        long a = x + nb[k].dx, b = y + nb[k].dy, c = z + nb[k].dz;
        if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz) continue;
      }
      std::size_t j = static_cast<std::size_t>(static_cast<long>(i) + lin[k]);
      if (accept(j)) stack.push_back(j);
    }
  }
}

// 1-D squared distance transform of f along a line with sample spacing h (Felzenszwalb &
// Huttenlocher 2012): lower envelope of the parabolas (h·(q - p))² + f(p).
void edt_line(std::vector<double>& f, double h, std::vector<double>& d, std::vector<int>& v, std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (std::isinf(f[q])) continue;
    double qq = q * h;
    while (k >= 0) {
      double pv = v[k] * h;
      double s = ((f[q] + qq * qq) - (f[v[k]] + pv * pv)) / (2 * (qq - pv));
      if (s <= z[k]) --k;
      else break;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -INFINITY : ((f[q] + qq * qq) - (f[v[k - 1]] + v[k - 1] * h * v[k - 1] * h)) / (2 * (qq - v[k - 1] * h));
    z[k + 1] = INFINITY;
  }
  if (k < 0) {
    std::fill(d.begin(), d.end(), INFINITY);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q * h) ++j;
    double dq = (q - v[j]) * h;
    d[q] = dq * dq + f[v[j]];
  }
}

}  // namespace

Components connected_components(const Grid& g, const Mask& m, int conn) {
  if (conn != 4 && conn != 8 && conn != 6 && conn != 18 && conn != 26)
    throw std::invalid_argument("connectivity must be 4, 8, 6, 18 or 26");
  Components c;
  c.label.assign(g.size(), 0);
  c.size.push_back(0);
  auto nb = neighbourhood(conn);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!m[i] || c.label[i]) continue;
    auto id = static_cast<std::uint32_t>(c.size.size());
    std::size_t n = 1;
    c.label[i] = id;
    flood(g, i, nb, [&](std::size_t j) {
      if (!m[j] || c.label[j]) return false;
      c.label[j] = id;
      ++n;
      return true;
    });
    c.size.push_back(n);
  }
  return c;
}

Mask largest_component(const Grid& g, const Mask& m, int conn) {
  Components c = connected_components(g, m, conn);
  Mask out(g.size(), 0);
  if (c.size.size() < 2) return out;
  auto best = static_cast<std::uint32_t>(std::max_element(c.size.begin() + 1, c.size.end()) - c.size.begin());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = c.label[i] == best;
  return out;
}

std::vector<double> squared_distance(const Grid& g, const Mask& target) {
  std::vector<double> d(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) d[i] = target[i] ? 0.0 : INFINITY;
  std::size_t nmax = std::max({g.n[0], g.n[1], g.n[2]});
  std::vector<double> out(nmax), z(nmax + 1);
  std::vector<int> v(nmax);
  // Lines along y and z are gathered kBlock at a time from consecutive x, so every
  // cache line read from the strided axis is used whole.
  constexpr std::size_t kBlock = 16;
  std::vector<std::vector<double>> f(kBlock, std::vector<double>(nmax));
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t n = g.n[axis];
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? g.n[0] : g.n[0] * g.n[1];
    out.resize(n);
    for (auto& fb : f) fb.resize(n);
    const std::size_t xstep = axis == 0 ? 1 : kBlock;
    for (std::size_t zc = 0; zc < (axis == 2 ? 1 : g.n[2]); ++zc)
      for (std::size_t y = 0; y < (axis == 1 ? 1 : g.n[1]); ++y)
        for (std::size_t x0 = 0; x0 < (axis == 0 ? 1 : g.n[0]); x0 += xstep) {
          const std::size_t nb = axis == 0 ? 1 : std::min(kBlock, g.n[0] - x0);
          const std::size_t base = g.index(x0, y, zc);
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t b = 0; b < nb; ++b) f[b][i] = d[base + b + i * stride];
          for (std::size_t b = 0; b < nb; ++b) {
            edt_line(f[b], g.spacing[axis], out, v, z);
            std::copy(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n), f[b].begin());
          }
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t b = 0; b < nb; ++b) d[base + b + i * stride] = f[b][i];
        }
  }
  return d;
}

std::vector<double> depth(const Grid& g, const Mask& m) {
  Mask outside(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) outside[i] = !m[i];
  std::vector<double> d = squared_distance(g, outside);
  for (auto& x : d) x = std::sqrt(x);
  return d;
}

Mask erode(const Grid& g, const Mask& m, double r) {
  Mask outside(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) outside[i] = !m[i];
  std::vector<double> d = squared_distance(g, outside);
  Mask out(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = m[i] && d[i] > r * r;
  return out;
}

Mask dilate(const Grid& g, const Mask& m, double r) {
  std::vector<double> d = squared_distance(g, m);
  Mask out(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = d[i] <= r * r;
  return out;
}

Mask open(const Grid& g, const Mask& m, double r) { return dilate(g, erode(g, m, r), r); }
Mask close(const Grid& g, const Mask& m, double r) { return erode(g, dilate(g, m, r), r); }

Mask fill_holes(const Grid& g, const Mask& m, bool per_slice) {
  Mask outside(g.size(), 0);
  auto nb = neighbourhood(per_slice ? 4 : 6);
  auto seed = [&](std::size_t i) {
    if (m[i] || outside[i]) return;
    outside[i] = 1;
    flood(g, i, nb, [&](std::size_t j) {
      if (m[j] || outside[j]) return false;
      outside[j] = 1;
      return true;
    });
  };
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        bool border = x == 0 || y == 0 || x + 1 == g.n[0] || y + 1 == g.n[1] ||
                      (!per_slice && (z == 0 || z + 1 == g.n[2]));
        if (border) seed(g.index(x, y, z));
      }
  Mask out(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = !outside[i];
  return out;
}

Mask region_grow(const Grid& g, const std::vector<float>& img, const Mask& seeds, double lo, double hi, int conn,
                 const Mask& within) {
  Mask out(g.size(), 0);
  auto nb = neighbourhood(conn);
  auto ok = [&](std::size_t j) { return img[j] >= lo && img[j] <= hi && (within.empty() || within[j]); };
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!seeds[i] || out[i] || !ok(i)) continue;
    out[i] = 1;
    flood(g, i, nb, [&](std::size_t j) {
      if (out[j] || !ok(j)) return false;
      out[j] = 1;
      return true;
    });
  }
  return out;
}

std::size_t count(const Mask& m) {
  std::size_t n = 0;
  for (auto v : m) n += v != 0;
  return n;
}

}  // namespace fest::segbrain

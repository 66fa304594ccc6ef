// Region growing (components and hole filling: components.cpp; distance transform and
// morphology: distance.cpp).
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

}  // namespace

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

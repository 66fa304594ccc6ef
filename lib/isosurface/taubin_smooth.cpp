// Taubin lambda|mu smoothing: docs/isosurf.md "Smoothing".
#include "isosurface/taubin_smooth.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace fest::isosurface {

void taubin_smooth(Surface& s, int iterations, double lambda, double mu) {
  const std::size_t nv = s.vertices();
  if (iterations <= 0 || nv == 0) return;
  // undirected edges with their use counts: boundary (1) and non-manifold (> 2) edges pin
  // their vertices
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * s.triangles.size());
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::vector<char> fixed(nv, 0);
  std::vector<std::uint32_t> start(nv + 1, 0), nbr;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unique;
  for (std::size_t e = 0; e < edges.size();) {
    std::size_t f = e;
    while (f < edges.size() && edges[f] == edges[e]) ++f;
    if (f - e != 2) fixed[edges[e].first] = fixed[edges[e].second] = 1;
    unique.push_back(edges[e]);
    e = f;
  }
  for (const auto& [a, b] : unique) ++start[a + 1], ++start[b + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  nbr.resize(start[nv]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& [a, b] : unique) nbr[fill[a]++] = b, nbr[fill[b]++] = a;
  std::vector<double> x(s.xyz.begin(), s.xyz.end()), next(x.size());
  auto pass = [&](double f) {
    for (std::size_t v = 0; v < nv; ++v) {
      const std::uint32_t n0 = start[v], n1 = start[v + 1];
      if (fixed[v] || n0 == n1) {
        for (int a = 0; a < 3; ++a) next[3 * v + a] = x[3 * v + a];
        continue;
      }
      for (int a = 0; a < 3; ++a) {
        double m = 0;
        for (std::uint32_t q = n0; q < n1; ++q) m += x[3 * nbr[q] + a];
        m /= double(n1 - n0);
        next[3 * v + a] = x[3 * v + a] + f * (m - x[3 * v + a]);
      }
    }
    x.swap(next);
  };
  for (int it = 0; it < iterations; ++it) pass(lambda), pass(mu);
  for (std::size_t i = 0; i < x.size(); ++i) s.xyz[i] = static_cast<float>(x[i]);
}

}  // namespace fest::isosurface

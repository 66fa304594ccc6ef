// Mesh voxelization by ray parity (docs/lbmsim.md 2.8).
#include "lbm/voxelize.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"

namespace fest::lbm {

EdgeCount count_open_edges(const TriangleSoup& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  EdgeCount c;
  for (const auto& [edge, n] : uses) {
    if (n == 1) ++c.boundary;
    if (n > 2) ++c.nonmanifold;
  }
  return c;
}

std::size_t voxelize(const TriangleSoup& mesh, const VoxelizeOptions& o, Flags& flags) {
  if (mesh.triangles.empty() || mesh.vertices.empty()) throw bad_input("mesh has no triangles");
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) {
      if (!std::isfinite(v[a])) throw bad_input("mesh has a non-finite vertex coordinate");
      lo[a] = std::min(lo[a], v[a]);
      hi[a] = std::max(hi[a], v[a]);
    }
  // Transform p -> s p + t.
  double s = 1.0;
  std::array<double, 3> t{0, 0, 0};
  if (o.fit_box) {
    std::array<double, 6> r = o.region;
    if (std::all_of(r.begin(), r.end(), [](double v) { return v == 0; }))
      r = {0, 0, 0, double(flags.size[0]), double(flags.size[1]), double(flags.size[2])};
    double scale = 1e300;
    for (int a = 0; a < 3; ++a) {
      const double room = (r[3 + a] - r[a]) - 2 * o.margin;
      if (room <= 0) throw bad_input("fit region leaves no room inside a margin of {} cells", o.margin);
      const double ext = hi[a] - lo[a];
      if (ext > 0) scale = std::min(scale, room / ext);
    }
    if (!(scale < 1e300)) throw bad_input("mesh has zero extent");
    s = scale;
    for (int a = 0; a < 3; ++a) t[a] = 0.5 * (r[a] + r[3 + a]) - s * 0.5 * (lo[a] + hi[a]);
  }
  std::vector<std::array<double, 3>> p(mesh.vertices.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) p[i][a] = s * mesh.vertices[i][a] + t[a];

  const int nx = flags.size[0], ny = flags.size[1], nz = flags.size[2];
  // Crossings of each column's ray (x+1/2, y+1/2) with the triangles, in z.
  std::vector<std::vector<double>> hits(static_cast<std::size_t>(nx) * ny);
  const double jitter = 1e-7;  // keeps rays off shared edges and vertices
  for (const auto& tri : mesh.triangles) {
    const auto& A = p[tri[0]];
    const auto& B = p[tri[1]];
    const auto& C = p[tri[2]];
    const double x0 = std::min({A[0], B[0], C[0]}), x1 = std::max({A[0], B[0], C[0]});
    const double y0 = std::min({A[1], B[1], C[1]}), y1 = std::max({A[1], B[1], C[1]});
    const int i0 = std::max(0, static_cast<int>(std::floor(x0 - 0.5))), i1 = std::min(nx - 1, static_cast<int>(std::ceil(x1 - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::floor(y0 - 0.5))), j1 = std::min(ny - 1, static_cast<int>(std::ceil(y1 - 0.5)));
    const double det = (B[0] - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (B[1] - A[1]);
    if (det == 0) continue;  // parallel to the rays
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double px = i + 0.5 + jitter, py = j + 0.5 + 1.3 * jitter;
        // Barycentric coordinates in the xy projection.
        const double l1 = ((px - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (py - A[1])) / det;
        const double l2 = ((B[0] - A[0]) * (py - A[1]) - (px - A[0]) * (B[1] - A[1])) / det;
        const double l0 = 1 - l1 - l2;
        if (l0 < 0 || l1 < 0 || l2 < 0) continue;
        hits[static_cast<std::size_t>(j) * nx + i].push_back(l0 * A[2] + l1 * B[2] + l2 * C[2]);
      }
  }
  std::size_t marked = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      auto& h = hits[static_cast<std::size_t>(j) * nx + i];
      if (h.size() < 2) continue;
      std::sort(h.begin(), h.end());
      for (int k = 0; k < nz; ++k) {
        const double zc = k + 0.5;
        const std::size_t below = static_cast<std::size_t>(std::lower_bound(h.begin(), h.end(), zc) - h.begin());
        if (below % 2 == 1) {
          auto& id = flags.id[flags.index(i, j, k)];
          if (id == 0) {
            id = o.flag;
            ++marked;
          }
        }
      }
    }
  return marked;
}

}  // namespace fest::lbm

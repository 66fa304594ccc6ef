#include "feshape/assignment.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::feshape {

std::vector<MeshPoint> assign_points(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& positions,
                                     const std::vector<std::array<int, 3>>& tris, int threads) {
  // A non-finite node (a diverged fit, coordinates near the double range) would break the
  // tree's ordering; stop with a failure instead.
  for (const auto& x : positions)
    if (!x.allFinite()) throw make_error(Status::failure, "the model became non-finite (NaN) during fitting");
  const TriangleTree tree(positions, tris);
  std::vector<MeshPoint> r(points.size());
  constexpr std::size_t chunk = 256;
  parallel_for((points.size() + chunk - 1) / chunk, threads, [&](std::size_t c) {
    for (std::size_t i = c * chunk; i < std::min(points.size(), (c + 1) * chunk); ++i) r[i] = tree.closest(points[i]);
  });
  for (const MeshPoint& p : r)  // every squared distance overflowed to infinity
    if (p.face < 0) throw make_error(Status::failure, "point-to-model distances overflow double precision: rescale the points");
  return r;
}

Eigen::Vector2d material_point(const Triangulation& t, const MeshPoint& p) {
  const auto c = unwrapped_corners(t, p.face);
  double u = 0, v = 0;
  for (int i = 0; i < 3; ++i) {
    u += p.lambda[i] * c[i][0];
    v += p.lambda[i] * c[i][1];
  }
  if (v >= pi) v -= 2 * pi;
  return {std::clamp(u, -pi / 2, pi / 2), v};
}

ErrorStats error_stats(const std::vector<MeshPoint>& assigned) {
  ErrorStats s;
  s.count = assigned.size();
  if (assigned.empty()) return s;
  double sum = 0;
  for (const auto& p : assigned) {
    sum += p.dist;
    s.max = std::max(s.max, p.dist);
  }
  s.mean = sum / static_cast<double>(s.count);
  double sq = 0;
  for (const auto& p : assigned) sq += (p.dist - s.mean) * (p.dist - s.mean);
  s.var = sq / static_cast<double>(s.count);
  s.std = std::sqrt(s.var);
  return s;
}

}  // namespace fest::feshape

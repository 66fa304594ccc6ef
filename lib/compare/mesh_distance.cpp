#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <vector>

#include "compare/mesh_compare.hpp"
#include "compare/triangle_tree.hpp"
#include "core/polygon_triangulation.hpp"
#include "core/rng.hpp"

namespace fest::compare {

namespace {

Vec3 to_eigen(const Mesh::Point& p) { return Vec3(p[0], p[1], p[2]); }

// Triangles of every face: the fan of a convex polygon, ears of a concave one (so a
// concave face covers what it covers), exact for triangles.
std::vector<Triangle> triangles_of(const Mesh& mesh, const FaceList& beside) {
  std::vector<Triangle> out;
  out.reserve(mesh.n_faces() + beside.size());
  std::vector<Vec3> corners;
  std::vector<std::array<double, 3>> positions;
  auto add = [&] {
    if (corners.size() == 3) {
      out.push_back({corners[0], corners[1], corners[2]});
      return;
    }
    positions.clear();
    for (const Vec3& c : corners) positions.push_back({c[0], c[1], c[2]});
    for (const auto& t : triangulate_polygon(positions)) out.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
  };
  for (auto f : mesh.faces()) {
    corners.clear();
    for (auto v : mesh.fv_range(f)) corners.push_back(to_eigen(mesh.point(v)));
    add();
  }
  for (const auto& face : beside) {
    corners.clear();
    for (int v : face) corners.push_back(to_eigen(mesh.point(Mesh::VertexHandle(v))));
    add();
  }
  return out;
}

// Every vertex used by a face, then `extra` points distributed by area.
std::vector<Vec3> sample_surface(const Mesh& mesh, const FaceList& beside, const std::vector<Triangle>& tris,
                                 std::size_t extra, std::uint64_t seed) {
  std::vector<Vec3> samples;
  samples.reserve(mesh.n_vertices() + extra);
  std::vector<char> in_beside(beside.empty() ? 0 : mesh.n_vertices(), 0);
  for (const auto& face : beside)
    for (int v : face) in_beside[static_cast<std::size_t>(v)] = 1;
  for (auto v : mesh.vertices())
    if (!mesh.is_isolated(v) || (!in_beside.empty() && in_beside[static_cast<std::size_t>(v.idx())]))
      samples.push_back(to_eigen(mesh.point(v)));
  if (tris.empty() || extra == 0) return samples;
  std::vector<double> cumulative(tris.size());
  double total = 0;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    total += 0.5 * (tris[i].b - tris[i].a).cross(tris[i].c - tris[i].a).norm();
    cumulative[i] = total;
  }
  if (!(total > 0)) return samples;
  SplitMix64 rng{seed};  // lib/core/rng.hpp: the same samples (and figures) everywhere
  for (std::size_t s = 0; s < extra; ++s) {
    const double pick = rng.uniform() * total;
    std::size_t i = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                                             cumulative.begin());
    i = std::min(i, tris.size() - 1);
    // Uniform point in a triangle: sqrt warps the first coordinate (Turk 1990).
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    const Triangle& t = tris[i];
    samples.push_back((1 - r1) * t.a + r1 * (1 - r2) * t.b + r1 * r2 * t.c);
  }
  return samples;
}

double bbox_diagonal(const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (auto v : mesh.vertices()) box.extend(to_eigen(mesh.point(v)));
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

}  // namespace

namespace {

struct SideResult {
  double worst = 0, sum_sq = 0, sum = 0;
};

// Distances of `samples` to `other`, in kChunks fixed slices handed to `threads`
// workers; slices are combined in index order (deterministic floating-point sums).
SideResult one_side(const std::vector<Vec3>& samples, const TriangleTree& other, double resolution, int threads) {
  constexpr std::size_t kChunks = 64;
  std::vector<SideResult> parts(kChunks);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t c; (c = next.fetch_add(1)) < kChunks;) {
      const std::size_t begin = samples.size() * c / kChunks, end = samples.size() * (c + 1) / kChunks;
      SideResult& r = parts[c];
      for (std::size_t i = begin; i < end; ++i) {
        double dist = std::sqrt(other.squared_distance(samples[i]));
        if (dist <= resolution) dist = 0;
        r.worst = std::max(r.worst, dist);
        r.sum_sq += dist * dist;
        r.sum += dist;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  SideResult total;
  for (const SideResult& r : parts) {
    total.worst = std::max(total.worst, r.worst);
    total.sum_sq += r.sum_sq;
    total.sum += r.sum;
  }
  return total;
}

}  // namespace

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, std::size_t extra_samples, std::uint64_t seed,
                                 int threads) {
  return surface_distance(a, FaceList{}, b, FaceList{}, extra_samples, seed, threads);
}

SurfaceDistance surface_distance(const Mesh& a, const FaceList& beside_a, const Mesh& b, const FaceList& beside_b,
                                 std::size_t extra_samples, std::uint64_t seed, int threads) {
  SurfaceDistance d;
  std::vector<Triangle> ta = triangles_of(a, beside_a), tb = triangles_of(b, beside_b);
  const std::vector<Vec3> sa = sample_surface(a, beside_a, ta, extra_samples, seed);
  const std::vector<Vec3> sb = sample_surface(b, beside_b, tb, extra_samples, seed + 1);
  const TriangleTree tree_a(std::move(ta)), tree_b(std::move(tb));
  d.resolution = 1e-12 * std::max(bbox_diagonal(a), bbox_diagonal(b));
  d.samples_a = sa.size();
  d.samples_b = sb.size();

  threads = std::max(threads, 1);
  const SideResult ab = one_side(sa, tree_b, d.resolution, threads);
  const SideResult ba = one_side(sb, tree_a, d.resolution, threads);
  d.max_a_to_b = ab.worst;
  d.max_b_to_a = ba.worst;
  d.hausdorff = std::max(d.max_a_to_b, d.max_b_to_a);
  const double n = static_cast<double>(sa.size() + sb.size());
  if (n > 0) {
    d.rms = std::sqrt((ab.sum_sq + ba.sum_sq) / n);
    d.mean = (ab.sum + ba.sum) / n;
  }
  return d;
}

}  // namespace fest::compare

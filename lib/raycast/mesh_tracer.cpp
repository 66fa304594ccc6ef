#include "raycast/mesh_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fest::raycast {

MeshTracer::MeshTracer(std::vector<float> xyz, std::vector<std::array<std::uint32_t, 3>> triangles, std::array<double, 3> colour)
    : xyz_(std::move(xyz)), tri_(std::move(triangles)), colour_(colour) {
  if (!tri_.empty()) {
    nodes_.reserve(2 * tri_.size());
    nodes_.push_back({});
    build(0, static_cast<std::uint32_t>(tri_.size()));
  }
}

// Builds the subtree of triangles [begin, end) into nodes_[slot] (the caller reserved it);
// returns the slot. Median split along the longest axis of the centroids' box.
std::uint32_t MeshTracer::build(std::uint32_t begin, std::uint32_t end) {
  struct Item { std::uint32_t begin, end, slot; };
  std::vector<Item> stack{{begin, end, 0}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    Node n{};
    for (int a = 0; a < 3; ++a) n.lo[a] = INFINITY, n.hi[a] = -INFINITY;
    float clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (std::uint32_t t = it.begin; t < it.end; ++t)
      for (int a = 0; a < 3; ++a) {
        float c = 0;
        for (int v = 0; v < 3; ++v) {
          const float x = xyz_[3 * std::size_t{tri_[t][v]} + a];
          n.lo[a] = std::min(n.lo[a], x), n.hi[a] = std::max(n.hi[a], x);
          c += x / 3;
        }
        clo[a] = std::min(clo[a], c), chi[a] = std::max(chi[a], c);
      }
    if (it.end - it.begin <= 4) {
      n.first = it.begin, n.count = it.end - it.begin;
      nodes_[it.slot] = n;
      continue;
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
    const std::uint32_t mid = it.begin + (it.end - it.begin) / 2;
    auto centre = [&](const std::array<std::uint32_t, 3>& t) {
      return xyz_[3 * std::size_t{t[0]} + axis] + xyz_[3 * std::size_t{t[1]} + axis] + xyz_[3 * std::size_t{t[2]} + axis];
    };
    std::nth_element(tri_.begin() + it.begin, tri_.begin() + mid, tri_.begin() + it.end,
                     [&](const auto& a, const auto& b) { return centre(a) < centre(b); });
    n.first = static_cast<std::uint32_t>(nodes_.size());
    n.count = 0;
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[it.slot] = n;
    stack.push_back({it.begin, mid, n.first});
    stack.push_back({mid, it.end, n.first + 1});
  }
  return 0;
}

SurfaceHit MeshTracer::trace(const Ray& r) const {
  SurfaceHit hit;
  if (nodes_.empty() || !r.valid) return hit;
  const double o[3] = {r.origin[0], r.origin[1], r.origin[2]}, d[3] = {r.dir[0], r.dir[1], r.dir[2]};
  double inv[3];
  for (int a = 0; a < 3; ++a) inv[a] = 1.0 / d[a];
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t best_tri = 0;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    double t0 = r.t_min, t1 = best;
    bool miss = false;
    for (int a = 0; a < 3 && !miss; ++a) {
      double ta = (n.lo[a] - o[a]) * inv[a], tb = (n.hi[a] - o[a]) * inv[a];
      if (ta > tb) std::swap(ta, tb);
      if (std::isnan(ta) || std::isnan(tb)) continue;  // parallel ray inside the slab
      t0 = std::max(t0, ta), t1 = std::min(t1, tb);
      miss = t0 > t1;
    }
    if (miss) continue;
    if (n.count == 0) {
      if (top + 2 <= 128) stack[top++] = n.first, stack[top++] = n.first + 1;
      continue;
    }
    for (std::uint32_t t = n.first; t < n.first + n.count; ++t) {
      const float* A = &xyz_[3 * std::size_t{tri_[t][0]}];
      const float* B = &xyz_[3 * std::size_t{tri_[t][1]}];
      const float* C = &xyz_[3 * std::size_t{tri_[t][2]}];
      const double e1[3] = {double(B[0]) - A[0], double(B[1]) - A[1], double(B[2]) - A[2]};
      const double e2[3] = {double(C[0]) - A[0], double(C[1]) - A[1], double(C[2]) - A[2]};
      const double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
      const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
      if (std::abs(det) < 1e-300) continue;
      const double s[3] = {o[0] - A[0], o[1] - A[1], o[2] - A[2]};
      const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
      if (u < 0 || u > 1) continue;
      const double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
      const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
      if (v < 0 || u + v > 1) continue;
      const double t_hit = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
      if (t_hit >= r.t_min && t_hit < best) best = t_hit, best_tri = t;
    }
  }
  if (!(best < std::numeric_limits<double>::infinity())) return hit;
  const float* A = &xyz_[3 * std::size_t{tri_[best_tri][0]}];
  const float* B = &xyz_[3 * std::size_t{tri_[best_tri][1]}];
  const float* C = &xyz_[3 * std::size_t{tri_[best_tri][2]}];
  const Vec3 nrm = normalized(cross(Vec3{double(B[0]) - A[0], double(B[1]) - A[1], double(B[2]) - A[2]},
                                    Vec3{double(C[0]) - A[0], double(C[1]) - A[1], double(C[2]) - A[2]}));
  const double lambert = std::abs(dot(nrm, normalized(r.dir)));
  hit.t = best;
  for (int c = 0; c < 3; ++c) hit.rgb[c] = colour_[c] * (0.25 + 0.75 * lambert);
  return hit;
}

}  // namespace fest::raycast

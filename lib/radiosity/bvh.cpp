#include "radiosity/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fest::radiosity {

Bvh::Bvh(const std::vector<Polygon>& polygons) {
  for (const Polygon& p : polygons) {
    tris_.push_back({p.p[0], p.p[1] - p.p[0], p.p[2] - p.p[0]});
    if (p.n == 4) tris_.push_back({p.p[0], p.p[2] - p.p[0], p.p[3] - p.p[0]});
  }
  std::vector<Eigen::Vector3d> centres(tris_.size());
  for (std::size_t i = 0; i < tris_.size(); ++i) centres[i] = tris_[i].p0 + (tris_[i].e1 + tris_[i].e2) / 3.0;
  if (!tris_.empty()) build(0, static_cast<int>(tris_.size()), centres, 0);
}

int Bvh::build(int first, int count, std::vector<Eigen::Vector3d>& centres, int depth) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  Eigen::Vector3d clo = lo, chi = hi;
  for (int i = first; i < first + count; ++i) {
    const Tri& t = tris_[i];
    for (const Eigen::Vector3d& q : {t.p0, Eigen::Vector3d(t.p0 + t.e1), Eigen::Vector3d(t.p0 + t.e2)}) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    clo = clo.cwiseMin(centres[i]);
    chi = chi.cwiseMax(centres[i]);
  }
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  if (count <= 4 || depth > 40) {
    nodes_[id].first = first;
    nodes_[id].count = count;
    return id;
  }
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int mid = first + count / 2;
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), first);
  std::nth_element(order.begin(), order.begin() + count / 2, order.end(), [&](int a, int b) {
    return centres[a][axis] < centres[b][axis] || (centres[a][axis] == centres[b][axis] && a < b);
  });
  std::vector<Tri> t2(count);
  std::vector<Eigen::Vector3d> c2(count);
  for (int i = 0; i < count; ++i) {
    t2[i] = tris_[order[i]];
    c2[i] = centres[order[i]];
  }
  for (int i = 0; i < count; ++i) {
    tris_[first + i] = t2[i];
    centres[first + i] = c2[i];
  }
  const int l = build(first, mid - first, centres, depth + 1);
  const int r = build(mid, first + count - mid, centres, depth + 1);
  nodes_[id].left = l;
  nodes_[id].right = r;
  return id;
}

bool Bvh::occluded(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (nodes_.empty()) return false;
  const Eigen::Vector3d d = b - a;
  const Eigen::Vector3d inv(1.0 / d.x(), 1.0 / d.y(), 1.0 / d.z());
  const double tmin = 1e-9, tmax = 1 - 1e-9;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    double t0 = 0, t1 = 1;
    bool miss = false;
    for (int k = 0; k < 3; ++k) {
      double ta = (nd.lo[k] - a[k]) * inv[k], tb = (nd.hi[k] - a[k]) * inv[k];
      if (std::isnan(ta) || std::isnan(tb)) {  // ray parallel to the slab and on its plane
        if (a[k] < nd.lo[k] || a[k] > nd.hi[k]) miss = true;
        continue;
      }
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) {
        miss = true;
        break;
      }
    }
    if (miss) continue;
    if (nd.left < 0) {
      for (int i = nd.first; i < nd.first + nd.count; ++i) {
        const Tri& t = tris_[i];  // Moller-Trumbore
        const Eigen::Vector3d p = d.cross(t.e2);
        const double det = t.e1.dot(p);
        if (std::abs(det) < 1e-300) continue;
        const double id = 1.0 / det;
        const Eigen::Vector3d s = a - t.p0;
        const double u = s.dot(p) * id;
        if (u < 0 || u > 1) continue;
        const Eigen::Vector3d q = s.cross(t.e1);
        const double v = d.dot(q) * id;
        if (v < 0 || u + v > 1) continue;
        const double tt = t.e2.dot(q) * id;
        if (tt > tmin && tt < tmax) return true;
      }
    } else if (top + 2 <= 128) {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
    }
  }
  return false;
}

}  // namespace fest::radiosity

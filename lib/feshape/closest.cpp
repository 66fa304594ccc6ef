#include "feshape/closest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fest::feshape {

TrianglePoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c) {
  // Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi region of p decides.
  TrianglePoint r;
  auto done = [&](double la, double lb, double lc) {
    r.lambda = {la, lb, lc};
    r.dist2 = (p - (la * a + lb * b + lc * c)).squaredNorm();
    return r;
  };
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return done(1, 0, 0);
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return done(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return done(1 - t, t, 0);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return done(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return done(1 - t, 0, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return done(0, 1 - t, t);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) {  // degenerate (zero-area) triangle: the best of its three edges
    TrianglePoint best;
    best.dist2 = std::numeric_limits<double>::infinity();
    const Eigen::Vector3d* v[3] = {&a, &b, &c};
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& s = *v[e];
      const Eigen::Vector3d d = *v[(e + 1) % 3] - s;
      const double len2 = d.squaredNorm();
      const double t = len2 > 0 ? std::clamp((p - s).dot(d) / len2, 0.0, 1.0) : 0.0;
      const double d2e = (p - (s + t * d)).squaredNorm();
      if (d2e < best.dist2) {
        best.dist2 = d2e;
        best.lambda = {0, 0, 0};
        best.lambda[e] = 1 - t;
        best.lambda[(e + 1) % 3] = t;
      }
    }
    return best;
  }
  const double v = vb / denom, w = vc / denom;
  return done(1 - v - w, v, w);
}

TriangleTree::TriangleTree(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<int, 3>>& tris)
    : points_(points), tris_(tris) {
  order_.resize(tris.size());
  std::iota(order_.begin(), order_.end(), 0);
  centroid_.resize(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f)
    centroid_[f] = (points[tris[f][0]] + points[tris[f][1]] + points[tris[f][2]]) / 3.0;
  nodes_.reserve(2 * tris.size() + 1);
  if (!tris.empty()) build(0, static_cast<int>(tris.size()));
}

int TriangleTree::build(int begin, int end) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int i = begin; i < end; ++i)
    for (int k = 0; k < 3; ++k) {
      lo = lo.cwiseMin(points_[tris_[order_[i]][k]]);
      hi = hi.cwiseMax(points_[tris_[order_[i]][k]]);
    }
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  nodes_[id].begin = begin;
  nodes_[id].end = end;
  if (end - begin <= 4) return id;
  Eigen::Index axis;
  (hi - lo).maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](int x, int y) {
    const double cx = centroid_[x][axis], cy = centroid_[y][axis];
    return cx < cy || (cx == cy && x < y);
  });
  const int l = build(begin, mid);
  const int r = build(mid, end);
  nodes_[id].left = l;
  nodes_[id].right = r;
  return id;
}

namespace {
double box_distance2(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  return d.squaredNorm();
}
}  // namespace

void TriangleTree::search(int id, const Eigen::Vector3d& p, MeshPoint& best, double& best2) const {
  const Node& n = nodes_[id];
  if (n.left < 0) {
    for (int i = n.begin; i < n.end; ++i) {
      const int f = order_[i];
      const auto& t = tris_[f];
      const TrianglePoint q = closest_on_triangle(p, points_[t[0]], points_[t[1]], points_[t[2]]);
      if (q.dist2 < best2 || (q.dist2 == best2 && f < best.face)) {
        best2 = q.dist2;
        best.face = f;
        best.lambda = q.lambda;
      }
    }
    return;
  }
  const double dl = box_distance2(p, nodes_[n.left].lo, nodes_[n.left].hi);
  const double dr = box_distance2(p, nodes_[n.right].lo, nodes_[n.right].hi);
  const int first = dl <= dr ? n.left : n.right, second = dl <= dr ? n.right : n.left;
  const double d1 = std::min(dl, dr), d2 = std::max(dl, dr);
  if (d1 <= best2) search(first, p, best, best2);
  if (d2 <= best2) search(second, p, best, best2);
}

MeshPoint TriangleTree::closest(const Eigen::Vector3d& p) const {
  MeshPoint best;
  double best2 = std::numeric_limits<double>::infinity();
  if (!nodes_.empty()) search(0, p, best, best2);
  best.dist = std::sqrt(best2);
  return best;
}

MeshPoint closest_brute_force(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points,
                              const std::vector<std::array<int, 3>>& tris) {
  MeshPoint best;
  double best2 = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < tris.size(); ++f) {
    const TrianglePoint q = closest_on_triangle(p, points[tris[f][0]], points[tris[f][1]], points[tris[f][2]]);
    if (q.dist2 < best2) {
      best2 = q.dist2;
      best.face = static_cast<int>(f);
      best.lambda = q.lambda;
    }
  }
  best.dist = std::sqrt(best2);
  return best;
}

}  // namespace fest::feshape

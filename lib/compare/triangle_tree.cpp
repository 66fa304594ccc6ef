#include "compare/triangle_tree.hpp"

#include <algorithm>
#include <limits>

#include "core/closest_point.hpp"

namespace fest::compare {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return fest::closest_point_on_triangle(p, a, b, c, [&](double va, double vb, double vc) -> Vec3 {
    const double denom = va + vb + vc;
    if (!(denom > 0)) return a;  // degenerate (zero-area) triangle: its vertices were sampled anyway
    // Inside: the projection onto the plane. Taken along the normal rather than from the
    // barycentric weights vb/denom, vc/denom, whose cancellation on a thin triangle (the
    // ears of a concave polygon) puts a point lying on it 1e-11 away from itself.
    const Vec3 ab = b - a, ac = c - a;
    const Vec3 normal = ab.cross(ac);
    const double nn = normal.squaredNorm();
    if (nn > 0) return p - (normal.dot(p - a) / nn) * normal;
    const double v = vb / denom, w = vc / denom;
    return a + ab * v + ac * w;
  });
}

TriangleTree::TriangleTree(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  nodes_.reserve(triangles_.size() / 2 + 8);
  build(0, static_cast<std::uint32_t>(triangles_.size()));
}

std::uint32_t TriangleTree::build(std::uint32_t first, std::uint32_t count) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Eigen::AlignedBox3d box;
  for (std::uint32_t i = first; i < first + count; ++i) {
    box.extend(triangles_[i].a);
    box.extend(triangles_[i].b);
    box.extend(triangles_[i].c);
  }
  nodes_[index].box = box;
  if (count <= 4) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis;
  box.sizes().maxCoeff(&axis);
  const std::uint32_t half = count / 2;
  auto centroid = [axis](const Triangle& t) { return t.a[axis] + t.b[axis] + t.c[axis]; };
  std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half, triangles_.begin() + first + count,
                   [&](const Triangle& x, const Triangle& y) { return centroid(x) < centroid(y); });
  const std::uint32_t left = build(first, half);
  const std::uint32_t right = build(first + half, count - half);
  nodes_[index].first = left;
  nodes_[index].count = 0;
  nodes_[index].right = right;
  return index;
}

double TriangleTree::squared_distance(const Vec3& p) const {
  double best = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best;
  // Explicit stack; children are visited nearer box first so pruning bites early.
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.box.squaredExteriorDistance(p) >= best) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& t = triangles_[i];
        best = std::min(best, (closest_point_on_triangle(p, t.a, t.b, t.c) - p).squaredNorm());
      }
      continue;
    }
    const std::uint32_t left = node.first;
    const std::uint32_t right = node.right;
    const double dl = nodes_[left].box.squaredExteriorDistance(p);
    const double dr = nodes_[right].box.squaredExteriorDistance(p);
    if (top + 2 > 128) continue;  // depth is ~2 log2(n): unreachable for any real mesh
    if (dl < dr) {
      stack[top++] = right;
      stack[top++] = left;
    } else {
      stack[top++] = left;
      stack[top++] = right;
    }
  }
  return best;
}

}  // namespace fest::compare

#include "core/polygon_triangulation.hpp"

#include <cmath>

namespace fest {
namespace {

using Point2 = std::array<double, 2>;

double cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool same(const Point2& a, const Point2& b) { return a[0] == b[0] && a[1] == b[1]; }

// Inside or on the boundary of the counter-clockwise triangle abc.
bool in_triangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

std::vector<std::array<std::size_t, 3>> fan(std::size_t n) {
  std::vector<std::array<std::size_t, 3>> out;
  for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
  return out;
}

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::array<double, 3>>& corners) {
  const std::size_t n = corners.size();
  if (n < 3) return {};
  // Ear clipping costs O(n^2) tests per polygon at least; a polygon of thousands of
  // corners (a file's single outline) keeps the fan.
  if (n == 3 || n > max_ear_clipped_corners) return fan(n);
  // Newell's normal: robust for non-planar and concave polygons. Project onto the
  // plane of its largest component, oriented so the polygon runs counter-clockwise.
  double normal[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = corners[i];
    const auto& q = corners[(i + 1) % n];
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(normal[k]) > std::fabs(normal[axis])) axis = k;
  if (!(std::fabs(normal[axis]) > 0)) return fan(n);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<Point2> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = {corners[i][u], flip * corners[i][v]};

  std::vector<std::size_t> left(n);
  for (std::size_t i = 0; i < n; ++i) left[i] = i;
  std::vector<std::array<std::size_t, 3>> out;
  out.reserve(n - 2);
  // Try the ear at the second remaining corner first: for a convex polygon every such
  // ear is one, and the triangles are exactly the fan around corner 0.
  std::size_t start = 0, failures = 0;
  while (left.size() > 3) {
    const std::size_t m = left.size();
    const std::size_t ia = start % m, ib = (start + 1) % m, ic = (start + 2) % m;
    const Point2 &a = p[left[ia]], &b = p[left[ib]], &c = p[left[ic]];
    bool ear = cross(a, b, c) >= 0;
    for (std::size_t k = 0; ear && k < m; ++k) {
      if (k == ia || k == ib || k == ic) continue;
      const Point2& q = p[left[k]];
      // A corner at the same place as the ear's own (a slit visiting a vertex twice)
      // does not block it.
      if (same(q, a) || same(q, b) || same(q, c)) continue;
      ear = !in_triangle(q, a, b, c);
    }
    if (ear) {
      out.push_back({left[ia], left[ib], left[ic]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(ib));
      if (ib < ia) start = ia - 1;  // keep the same first corner after removing an earlier one
      else start = ia;
      failures = 0;
    } else if (++failures >= m) {
      // No ear (self-intersecting input): give up on the rest with a fan.
      for (std::size_t k = 1; k + 1 < m; ++k) out.push_back({left[0], left[k], left[k + 1]});
      return out;
    } else {
      start = (start + 1) % m;
    }
  }
  out.push_back({left[0], left[1], left[2]});
  return out;
}

}  // namespace fest

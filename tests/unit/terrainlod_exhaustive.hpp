#pragma once
// An exhaustive vertical error check for the terrainlod tests that shares no code with the
// library's error measure: every reference triangle (grid cell half, diagonal rule
// re-derived here) is clipped against every overlapping result triangle (Sutherland-
// Hodgman), and the difference of the two linear functions is evaluated at the corners of
// the clipped polygon, where it is largest.

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "terrainlod/height_grid.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/simplify.hpp"

namespace fest::test {

struct P {
  double x, y;
};

inline double cross(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Sutherland-Hodgman: polygon clipped by the half-plane left of a -> b (ccw triangle).
inline std::vector<P> clip(const std::vector<P>& poly, P a, P b) {
  std::vector<P> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P p = poly[k], q = poly[(k + 1) % poly.size()];
    const double dp = cross(a, b, p), dq = cross(a, b, q);
    if (dp >= 0) out.push_back(p);
    if ((dp >= 0) != (dq >= 0)) {
      const double t = dp / (dp - dq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

// Linear interpolation of z over a triangle at (x, y) by barycentric coordinates.
inline double lerp3(const std::array<P, 3>& t, const std::array<double, 3>& z, P p) {
  const double d = cross(t[0], t[1], t[2]);
  return (cross(p, t[1], t[2]) * z[0] + cross(t[0], p, t[2]) * z[1] + cross(t[0], t[1], p) * z[2]) / d;
}

// The reference triangles of the grid with the diagonal rule re-derived here.
inline bool ne_cell(const terrainlod::HeightGrid& g, int i, int j, terrainlod::DiagonalRule rule) {
  if (rule == terrainlod::DiagonalRule::ne) return true;
  if (rule == terrainlod::DiagonalRule::alternate) return (i + j) % 2 == 0;
  return std::abs(g.at(i + 1, j + 1) - g.at(i, j)) <= std::abs(g.at(i, j + 1) - g.at(i + 1, j));
}

// Largest vertical distance of one counter-clockwise triangle from the grid's surface.
inline double exhaustive_triangle_error(const terrainlod::HeightGrid& g, const terrainlod::GridPoint& a,
                                        const terrainlod::GridPoint& b, const terrainlod::GridPoint& c,
                                        terrainlod::DiagonalRule rule) {
  double worst = 0;
  const std::array<P, 3> T{P{a.x, a.y}, P{b.x, b.y}, P{c.x, c.y}};
  const std::array<double, 3> Tz{a.z, b.z, c.z};
  const int i0 = static_cast<int>(std::min({a.x, b.x, c.x})), i1 = static_cast<int>(std::max({a.x, b.x, c.x}));
  const int j0 = static_cast<int>(std::min({a.y, b.y, c.y})), j1 = static_cast<int>(std::max({a.y, b.y, c.y}));
  for (int j = j0; j < std::min(j1, g.height - 1); ++j)
    for (int i = i0; i < std::min(i1, g.width - 1); ++i) {
      const P p00{double(i), double(j)}, p10{i + 1.0, double(j)}, p01{double(i), j + 1.0}, p11{i + 1.0, j + 1.0};
      const double h00 = g.at(i, j), h10 = g.at(i + 1, j), h01 = g.at(i, j + 1), h11 = g.at(i + 1, j + 1);
      std::vector<std::pair<std::array<P, 3>, std::array<double, 3>>> refs;
      if (ne_cell(g, i, j, rule)) {
        refs.push_back({{p00, p10, p11}, {h00, h10, h11}});
        refs.push_back({{p00, p11, p01}, {h00, h11, h01}});
      } else {
        refs.push_back({{p00, p10, p01}, {h00, h10, h01}});
        refs.push_back({{p10, p11, p01}, {h10, h11, h01}});
      }
      for (const auto& [R, Rz] : refs) {
        std::vector<P> poly(R.begin(), R.end());
        for (int e = 0; e < 3 && !poly.empty(); ++e) poly = clip(poly, T[e], T[(e + 1) % 3]);
        for (const P& p : poly) worst = std::max(worst, std::abs(lerp3(T, Tz, p) - lerp3(R, Rz, p)));
      }
    }
  return worst;
}

inline double exhaustive_error(const terrainlod::HeightGrid& g, const terrainlod::Tin& tin,
                               terrainlod::DiagonalRule rule) {
  double worst = 0;
  for (const auto& tri : tin.triangles)
    worst = std::max(worst, exhaustive_triangle_error(g, tin.vertices[tri[0]], tin.vertices[tri[1]],
                                                      tin.vertices[tri[2]], rule));
  return worst;
}

}  // namespace fest::test

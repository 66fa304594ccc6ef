#pragma once
// The closest point of a triangle to a point, by Ericson's Voronoi-region test
// (Real-Time Collision Detection, 5.1.5: ClosestPtPointTriangle). Used by lib/compare
// (distances between surfaces, docs/fcompare.md) and lib/softobj (triangle skeletons,
// docs/softobj.md §1). Header-only and generic over the vector type (Eigen's Vector3d
// in both), so lib/core needs no linear-algebra library.

namespace fest {

// In a vertex or edge region the answer follows from the dot products. In the face
// region it is `inside(va, vb, vc)`, given the unnormalised barycentric weights: callers
// differ in how they take the point there (see the overload below and lib/compare).
template <class Vec, class Inside>
Vec closest_point_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c, Inside&& inside) {
  const Vec ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  return inside(va, vb, vc);
}

// Ericson's face-region point: a + ab v + ac w with v, w the normalised weights.
template <class Vec>
Vec closest_point_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  return closest_point_on_triangle(p, a, b, c, [&](double va, double vb, double vc) -> Vec {
    const double denom = 1.0 / (va + vb + vc);
    return a + (b - a) * (vb * denom) + (c - a) * (vc * denom);
  });
}

}  // namespace fest

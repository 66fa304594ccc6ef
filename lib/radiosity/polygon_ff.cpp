#include "radiosity/polygon_ff.hpp"

#include <cmath>
#include <vector>

#include "radiosity/scene.hpp"

namespace fest::radiosity {

double point_polygon_ff(const Eigen::Vector3d& y, const Eigen::Vector3d& n, const Polygon& poly) {
  // Clip to n . (p - y) >= 0 (Sutherland-Hodgman against one plane; at most 5 corners
  // remain of 4, kept on the stack: this runs once per element per shot).
  Eigen::Vector3d in[8];
  int m = 0;
  for (int k = 0; k < poly.n; ++k) {
    const Eigen::Vector3d& a = poly.p[k];
    const Eigen::Vector3d& b = poly.p[(k + 1) % poly.n];
    const double da = n.dot(a - y), db = n.dot(b - y);
    if (da >= 0) in[m++] = a;
    if ((da >= 0) != (db >= 0)) in[m++] = a + (b - a) * (da / (da - db));
  }
  if (m < 3) return 0;
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    const Eigen::Vector3d r0 = in[k] - y, r1 = in[(k + 1) % m] - y;
    const Eigen::Vector3d c = r0.cross(r1);
    const double cn = c.norm();
    if (cn <= 0) continue;
    const double gamma = std::atan2(cn, r0.dot(r1));
    sum += gamma * n.dot(c) / cn;
  }
  return std::abs(sum) / (2 * M_PI);
}

double polygon_polygon_ff(const Polygon& a, const Polygon& b, int cells) {
  static const double x4[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double w4[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  const Eigen::Vector3d n = a.normal();
  const double area = a.area();
  if (!(area > 0)) return 0;
  double sum = 0;
  for (const Polygon& c : split_polygon(a, a.longest_edge() / std::max(1, cells))) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double s = 0.5 * (x4[i] + 1), t = 0.5 * (x4[j] + 1);
        Eigen::Vector3d p;
        double jac;
        if (c.n == 4) {
          p = c.sample(s, t);
          const Eigen::Vector3d ds = (1 - t) * (c.p[1] - c.p[0]) + t * (c.p[2] - c.p[3]);
          const Eigen::Vector3d dt = (1 - s) * (c.p[3] - c.p[0]) + s * (c.p[2] - c.p[1]);
          jac = ds.cross(dt).norm();
        } else {  // Duffy map p = p0 + s (p1 - p0) + s t (p2 - p1)
          p = c.p[0] + s * (c.p[1] - c.p[0]) + s * t * (c.p[2] - c.p[1]);
          jac = s * (c.p[1] - c.p[0]).cross(c.p[2] - c.p[1]).norm();
        }
        sum += 0.25 * w4[i] * w4[j] * jac * point_polygon_ff(p, n, b);
      }
  }
  return sum / area;
}

}  // namespace fest::radiosity

// Node flags and node classes (docs/lbmsim.md "Boundary conditions", "Geometry").
#include "lbm/geometry.hpp"

#include <cmath>

namespace fest::lbm {

Flags shape_flags(const Case& c) {
  Flags f;
  f.size = c.size;
  f.id.assign(c.cells(), 0);
  for (const Shape& s : c.shapes) {
    for (int z = 0; z < c.size[2]; ++z)
      for (int y = 0; y < c.size[1]; ++y)
        for (int x = 0; x < c.size[0]; ++x) {
          const double p[3] = {x + 0.5, y + 0.5, c.dim == 3 ? z + 0.5 : 0.0};
          bool inside = false;
          if (s.kind == Shape::Kind::box) {
            inside = true;
            for (int a = 0; a < c.dim; ++a) inside = inside && p[a] >= s.lo[a] && p[a] <= s.hi[a];
          } else {
            double r2 = 0;
            for (int a = 0; a < c.dim; ++a) {
              if (s.kind == Shape::Kind::cylinder && c.dim == 3 && a == s.axis) continue;
              r2 += (p[a] - s.center[a]) * (p[a] - s.center[a]);
            }
            inside = r2 <= s.radius * s.radius;
          }
          if (inside) f.id[f.index(x, y, z)] = s.flag;
        }
  }
  return f;
}

double link_fraction(const Case& c, const std::array<double, 3>& p, const std::array<double, 3>& d) {
  double best = -1;
  for (const Shape& s : c.shapes) {
    if (s.kind == Shape::Kind::box) continue;
    // Solve |(p + t d - centre) restricted to the shape's axes| = r for the entry t in (0, 1].
    double a = 0, b = 0, k = 0;
    for (int ax = 0; ax < c.dim; ++ax) {
      if (s.kind == Shape::Kind::cylinder && c.dim == 3 && ax == s.axis) continue;
      const double e = p[ax] - s.center[ax];
      a += d[ax] * d[ax];
      b += 2 * e * d[ax];
      k += e * e;
    }
    k -= s.radius * s.radius;
    if (a == 0 || k <= 0) continue;  // parallel to the axis, or p inside the shape
    const double disc = b * b - 4 * a * k;
    if (disc < 0) continue;
    const double t = (-b - std::sqrt(disc)) / (2 * a);
    if (t > 0 && t <= 1 && (best < 0 || t < best)) best = t;
  }
  return best;
}

namespace {
int face_priority(Face::Kind k) {
  switch (k) {
    case Face::Kind::moving: return 4;
    case Face::Kind::wall: return 3;
    case Face::Kind::velocity: return 2;
    case Face::Kind::pressure: return 1;
    default: return 0;
  }
}
}  // namespace

std::array<double, 3> inlet_velocity(const Case& c, int face, int x, int y, int z) {
  const Face& f = c.faces[face];
  const int axis = face / 2;
  const double sign = face % 2 == 0 ? 1.0 : -1.0;  // inward normal
  std::array<double, 3> u{0, 0, 0};
  if (f.u_vector)
    u = f.u;
  else
    u[axis] = sign * f.speed;
  if (f.profile == Face::Profile::parabolic) {
    const int p[3] = {x, y, z};
    double factor = 1.0;
    for (int a = 0; a < c.dim; ++a) {
      if (a == axis) continue;
      const double s = (p[a] + 0.5) / c.size[a];
      factor *= 4.0 * s * (1.0 - s);
    }
    for (double& v : u) v *= factor;
  }
  return u;
}

NodeClass classify(const Case& c, const Flags& flags, int x, int y, int z) {
  int p[3] = {x, y, z};
  int best_face = -1;
  for (int a = 0; a < c.dim; ++a) {
    if (p[a] >= 0 && p[a] < c.size[a]) continue;
    const int face = 2 * a + (p[a] < 0 ? 0 : 1);
    if (c.faces[face].kind == Face::Kind::periodic) {
      p[a] = (p[a] + c.size[a]) % c.size[a];
      continue;
    }
    if (best_face < 0 || face_priority(c.faces[face].kind) > face_priority(c.faces[best_face].kind)) best_face = face;
  }
  NodeClass n;
  if (best_face < 0) {
    const std::uint8_t id = flags.id[flags.index(p[0], p[1], c.dim == 3 ? p[2] : 0)];
    if (id != 0) {
      n.kind = NodeClass::Kind::solid;
      n.id = id;
    }
    return n;
  }
  const Face& f = c.faces[best_face];
  n.face = best_face;
  switch (f.kind) {
    case Face::Kind::moving:
      n.kind = NodeClass::Kind::solid;
      n.u = f.u;
      break;
    case Face::Kind::wall: n.kind = NodeClass::Kind::solid; break;
    case Face::Kind::velocity:
      n.kind = NodeClass::Kind::inlet;
      n.u = inlet_velocity(c, best_face, x, y, z);
      break;
    case Face::Kind::pressure:
      n.kind = NodeClass::Kind::outlet;
      n.rho = f.rho;
      break;
    default: break;
  }
  return n;
}

}  // namespace fest::lbm

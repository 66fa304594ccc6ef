#include "fluidsim/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace fest::fluidsim {

Layout Layout::make(int dim, std::array<int, 3> n, std::array<Boundary, 3> bc, double h) {
  if (dim != 2 && dim != 3) throw bad_input("dims must be 2 or 3 integers in [3, 1024]");
  Layout l;
  l.dim = dim;
  for (int a = 0; a < 3; ++a) {
    if (a < dim) {
      if (n[a] < 3 || n[a] > 1024) throw bad_input("dims must be 2 or 3 integers in [3, 1024]");
      l.n[a] = n[a];
      l.bc[a] = bc[a];
      l.size[a] = bc[a] == Boundary::closed ? n[a] + 2 : n[a];
    } else {
      l.n[a] = 1;
      l.bc[a] = Boundary::periodic;
      l.size[a] = 1;
    }
  }
  if (!(h > 0.0) || !std::isfinite(h)) throw bad_input("h must be a positive finite number");
  l.h = h;
  return l;
}

int Layout::fold(int axis, int i, bool& flipped) const noexcept {
  flipped = false;
  if (!active(axis)) return 0;
  const int s = size[axis];
  if (bc[axis] == Boundary::periodic) {
    i %= s;
    return i < 0 ? i + s : i;
  }
  // Mirror about node 0 and node s-1 (the walls); repeated for reaches beyond one cell.
  const int last = s - 1;
  for (;;) {
    if (i < 0) {
      i = -i;
      flipped = !flipped;
    } else if (i > last) {
      i = 2 * last - i;
      flipped = !flipped;
    } else {
      return i;
    }
  }
}

AxisNeighbours neighbours(const Layout& layout, int axis, int reach) {
  AxisNeighbours t;
  const int s = layout.size[axis];
  t.plus.resize(s);
  t.minus.resize(s);
  t.plus_flip.resize(s);
  t.minus_flip.resize(s);
  for (int i = 0; i < s; ++i) {
    bool f = false;
    t.plus[i] = layout.fold(axis, i + reach, f);
    t.plus_flip[i] = f;
    t.minus[i] = layout.fold(axis, i - reach, f);
    t.minus_flip[i] = f;
  }
  return t;
}

std::array<double, 3> confine(const Layout& layout, std::array<double, 3> p) noexcept {
  for (int a = 0; a < 3; ++a) {
    if (!layout.active(a)) {
      p[a] = 0.0;
      continue;
    }
    const double s = layout.size[a];
    if (layout.bc[a] == Boundary::closed) {
      p[a] = std::clamp(p[a], 0.0, s - 1.0);
    } else {
      p[a] = std::fmod(p[a], s);
      if (p[a] < 0.0) p[a] += s;
      if (p[a] >= s) p[a] = 0.0;  // -tiny + s rounds to s
    }
  }
  return p;
}

Corners corners(const Layout& layout, const std::array<double, 3>& q) noexcept {
  if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) {
    // A trace through a non-finite velocity: propagate NaN into the sample so the step's
    // finiteness check reports it (instead of indexing with an undefined position).
    Corners bad;
    bad.weight.fill(std::numeric_limits<double>::quiet_NaN());
    return bad;
  }
  const std::array<double, 3> p = confine(layout, q);
  int i0[3], i1[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    const int s = layout.size[a];
    if (s == 1) {
      i0[a] = i1[a] = 0;
      t[a] = 0.0;
      continue;
    }
    int f = static_cast<int>(std::floor(p[a]));
    if (layout.bc[a] == Boundary::closed) {
      f = std::min(f, s - 2);
      i0[a] = f;
      i1[a] = f + 1;
    } else {
      f = std::min(f, s - 1);
      i0[a] = f;
      i1[a] = f + 1 == s ? 0 : f + 1;
    }
    t[a] = p[a] - f;
  }
  Corners c;
  for (int corner = 0; corner < 8; ++corner) {
    const int bx = corner & 1, by = (corner >> 1) & 1, bz = (corner >> 2) & 1;
    c.index[corner] = layout.index(bx ? i1[0] : i0[0], by ? i1[1] : i0[1], bz ? i1[2] : i0[2]);
    c.weight[corner] = (bx ? t[0] : 1.0 - t[0]) * (by ? t[1] : 1.0 - t[1]) * (bz ? t[2] : 1.0 - t[2]);
  }
  return c;
}

double sample(const Layout& layout, const Field& f, const std::array<double, 3>& p) noexcept {
  return corners(layout, p).apply(f);
}

void enforce_walls(const Layout& layout, Velocity& u, bool no_slip) {
  for (int axis = 0; axis < layout.dim; ++axis) {
    if (!layout.closed(axis)) continue;
    const int walls[2] = {0, layout.size[axis] - 1};
    for (int c = 0; c < layout.dim; ++c) {
      if (velocity_parity(c, axis, no_slip) != Parity::odd) continue;
      for (int w : walls) {
        // Every node of the plane index[axis] == w, in memory order (inner loop along the
        // lower of the two other axes).
        const int lo = axis == 0 ? 1 : 0, hi = axis == 2 ? 1 : 2;
        for (int k = 0; k < layout.size[hi]; ++k)
          for (int j = 0; j < layout.size[lo]; ++j) {
            std::array<int, 3> ijk{};
            ijk[axis] = w;
            ijk[lo] = j;
            ijk[hi] = k;
            u[c][layout.index(ijk[0], ijk[1], ijk[2])] = 0.0;
          }
      }
    }
  }
}

}  // namespace fest::fluidsim

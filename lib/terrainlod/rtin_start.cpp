#include "terrainlod/rtin_start.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <utility>

#include "core/error.hpp"

namespace fest::terrainlod {
namespace {

struct LatticePoint {
  int i = 0, j = 0;
};

LatticePoint midpoint(LatticePoint a, LatticePoint b) { return {(a.i + b.i) / 2, (a.j + b.j) / 2}; }

class RtinBuilder {
 public:
  RtinBuilder(const ReferenceSurface& dem, const SquareLattice& lat, double limit, const TriangleMeasure& measure)
      : dem_(dem), lat_(lat), limit_(limit), measure_(measure),
        over_(static_cast<std::size_t>(lat.n + 1) * (lat.n + 1), 0),
        flipped_(static_cast<std::size_t>(lat.n) * lat.n, 0),
        vertex_of_(static_cast<std::size_t>(lat.n + 1) * (lat.n + 1), -1) {}

  std::optional<RtinStart> run(const std::vector<std::uint8_t>& locked_points) {
    // A locked point is the hypotenuse midpoint of the triangles that insert it: flagging
    // it splits them (and, by the propagation below, their ancestors and neighbours).
    for (std::size_t p = 0; p < over_.size(); ++p)
      if (locked_points[p]) over_[p] = 1;
    if (!measure_cells()) return std::nullopt;
    propagate();
    const int n = lat_.n;
    select({0, 0}, {n, n}, {n, 0});
    select({n, n}, {0, 0}, {0, n});
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci)
        if (flipped_[static_cast<std::size_t>(cj) * n + ci]) {
          const LatticePoint p00{ci, cj}, p10{ci + 1, cj}, p01{ci, cj + 1}, p11{ci + 1, cj + 1};
          if (rtin_ne(ci, cj)) {  // the RTIN's diagonal is SW-NE: the cell takes NW-SE
            emit(p00, p10, p01);
            emit(p10, p11, p01);
          } else {
            emit(p00, p10, p11);
            emit(p00, p11, p01);
          }
          ++result_.flipped_cells;
        }
    result_.locked.reserve(result_.tin.vertices.size());
    for (const auto& v : result_.tin.vertices) {
      const int i = (static_cast<int>(v.x) - lat_.x0) / lat_.step, j = (static_cast<int>(v.y) - lat_.y0) / lat_.step;
      result_.locked.push_back(locked_points[index(i, j)]);
    }
    return std::move(result_);
  }

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * (lat_.n + 1) + i; }
  std::size_t index(LatticePoint p) const { return index(p.i, p.j); }

  GridPoint point(LatticePoint p) const {
    const int x = lat_.x0 + p.i * lat_.step, y = lat_.y0 + p.j * lat_.step;
    return {double(x), double(y), dem_.sample(x, y)};
  }

  // Exactly measured within the limit? The corners in any order.
  bool fits(LatticePoint a, LatticePoint b, LatticePoint c) {
    GridPoint pa = point(a), pb = point(b), pc = point(c);
    if (twice_area(pa, pb, pc) < 0) std::swap(pb, pc);
    ++result_.measured;
    return measure_(pa, pb, pc, limit_) <= limit_;
  }

  // The smallest RTIN triangles split every 2 x 2 block of cells by the diagonals through
  // its centre (the right-angle corner of their parents), so cell (ci, cj) has the SW-NE
  // diagonal exactly when ci + cj is even.
  static bool rtin_ne(int ci, int cj) { return (ci + cj) % 2 == 0; }

  // Every cell with the RTIN's diagonal, or else the other one; a cell that takes the
  // other diagonal needs both its RTIN halves' parents split, so their hypotenuse
  // midpoints (the cell's two corners off the RTIN diagonal) are flagged.
  bool measure_cells() {
    const int n = lat_.n;
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci) {
        const LatticePoint p00{ci, cj}, p10{ci + 1, cj}, p01{ci, cj + 1}, p11{ci + 1, cj + 1};
        const bool ne = rtin_ne(ci, cj);
        const bool rtin_fits = ne ? fits(p00, p10, p11) && fits(p00, p11, p01) : fits(p00, p10, p01) && fits(p10, p11, p01);
        if (rtin_fits) continue;
        const bool other_fits = ne ? fits(p00, p10, p01) && fits(p10, p11, p01) : fits(p00, p10, p11) && fits(p00, p11, p01);
        if (!other_fits) return false;
        flipped_[static_cast<std::size_t>(cj) * n + ci] = 1;
        if (ne) {
          over_[index(p10)] = 1;
          over_[index(p01)] = 1;
        } else {
          over_[index(p00)] = 1;
          over_[index(p11)] = 1;
        }
      }
    return true;
  }

  // The splittable triangles from the finest level up (Martini's numbering: id 2 and 3 are
  // the two half-squares; each further bit from the lowest chooses a child), each flagging
  // its hypotenuse midpoint when a child's midpoint is flagged or it is over the limit.
  // Both triangles sharing a hypotenuse are on the same level, so a flag is final before
  // the next coarser level reads it.
  void propagate() {
    const int n = lat_.n;
    const long long splittable = 2LL * n * n - 2;
    for (long long t = splittable - 1; t >= 0; --t) {
      long long id = t + 2;
      LatticePoint a, b, c;
      if (id & 1) {
        a = {0, 0}, b = {n, n}, c = {n, 0};
      } else {
        a = {n, n}, b = {0, 0}, c = {0, n};
      }
      while ((id >>= 1) > 1) {
        const LatticePoint m = midpoint(a, b);
        if (id & 1) {
          b = a;
          a = c;
        } else {
          a = b;
          b = c;
        }
        c = m;
      }
      const LatticePoint m = midpoint(a, b);
      std::uint8_t& flag = over_[index(m)];
      if (flag) continue;
      // The children are splittable themselves (not half cells) when the hypotenuse
      // spans more than two cells.
      if (std::abs(a.i - b.i) + std::abs(a.j - b.j) > 2 &&
          (over_[index(midpoint(c, a))] || over_[index(midpoint(b, c))])) {
        flag = 1;
        continue;
      }
      if (!fits(a, b, c)) flag = 1;
    }
  }

  // Top-down: split every triangle whose hypotenuse midpoint is flagged.
  void select(LatticePoint a, LatticePoint b, LatticePoint c) {
    if (std::abs(a.i - c.i) + std::abs(a.j - c.j) > 1) {
      const LatticePoint m = midpoint(a, b);
      if (over_[index(m)]) {
        select(c, a, m);
        select(b, c, m);
        return;
      }
    } else {
      // A smallest triangle: half a cell, emitted with the cell when it was flipped.
      const int ci = std::min(a.i, b.i), cj = std::min(a.j, b.j);
      if (flipped_[static_cast<std::size_t>(cj) * lat_.n + ci]) return;
    }
    emit(a, b, c);
  }

  int vertex(LatticePoint p) {
    int& v = vertex_of_[index(p)];
    if (v < 0) {
      v = static_cast<int>(result_.tin.vertices.size());
      result_.tin.vertices.push_back(point(p));
    }
    return v;
  }

  void emit(LatticePoint a, LatticePoint b, LatticePoint c) {
    std::array<int, 3> t{vertex(a), vertex(b), vertex(c)};
    const auto& v = result_.tin.vertices;
    if (twice_area(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])]) < 0)
      std::swap(t[1], t[2]);
    result_.tin.triangles.push_back(t);
  }

  const ReferenceSurface& dem_;
  SquareLattice lat_;
  double limit_;
  const TriangleMeasure& measure_;
  std::vector<std::uint8_t> over_;     // per lattice point: the triangles it bisects must split
  std::vector<std::uint8_t> flipped_;  // per cell: takes the diagonal the RTIN does not have
  std::vector<int> vertex_of_;         // per lattice point: vertex id in the result, -1 = none
  RtinStart result_;
};

}  // namespace

std::optional<RtinStart> rtin_start_mesh(const ReferenceSurface& dem, const SquareLattice& lattice,
                                         const std::vector<std::uint8_t>& locked_points, double limit,
                                         const TriangleMeasure& measure) {
  const int n = lattice.n;
  if (n < 1 || (n & (n - 1)) != 0 || n > (1 << 15))
    throw usage_error("RTIN start mesh: lattice cells per side must be a power of two up to 32768 (got {})", n);
  if (lattice.step < 1 || lattice.x0 < 0 || lattice.y0 < 0 ||
      static_cast<long long>(lattice.x0) + static_cast<long long>(n) * lattice.step > dem.width() - 1 ||
      static_cast<long long>(lattice.y0) + static_cast<long long>(n) * lattice.step > dem.height() - 1)
    throw usage_error("RTIN start mesh: lattice ({}, {}) + {} x {} outside the DEM ({} x {})", lattice.x0, lattice.y0, n,
                      lattice.step, dem.width(), dem.height());
  if (locked_points.size() != static_cast<std::size_t>(n + 1) * (n + 1))
    throw usage_error("RTIN start mesh: {} locked flags for {} lattice points", locked_points.size(),
                      static_cast<std::size_t>(n + 1) * (n + 1));
  RtinBuilder builder(dem, lattice, limit, measure);
  return builder.run(locked_points);
}

}  // namespace fest::terrainlod

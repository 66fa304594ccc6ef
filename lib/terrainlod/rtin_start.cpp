#include "terrainlod/rtin_start.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <utility>

#include "core/error.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {
namespace {

struct LatticePoint {
  int i = 0, j = 0;
  bool operator==(const LatticePoint& o) const { return i == o.i && j == o.j; }
};

// An RTIN triangle: hypotenuse a-b, right angle at c. Its children are (c, a, m) and
// (b, c, m), m the hypotenuse's midpoint; the triangle across the hypotenuse (its
// partner, same size) is (b, a, 2m - c).
struct Rtri {
  LatticePoint a, b, c;
};

LatticePoint midpoint(LatticePoint a, LatticePoint b) { return {(a.i + b.i) / 2, (a.j + b.j) / 2}; }
LatticePoint reflect(LatticePoint p, LatticePoint centre) { return {2 * centre.i - p.i, 2 * centre.j - p.j}; }

class RtinBuilder {
 public:
  RtinBuilder(const ReferenceSurface& dem, const SquareLattice& lat, const std::vector<std::uint8_t>& locked,
              double limit, const TriangleMeasure& measure, const PointHeight& reference_height)
      : dem_(dem), lat_(lat), locked_(locked), limit_(limit), measure_(measure), reference_height_(reference_height),
        split_(points(), 0), state_(2 * points(), kUnknown), cell_(static_cast<std::size_t>(lat.n) * lat.n, 0),
        vertex_of_(points(), -1) {}

  std::optional<RtinStart> run() {
    const int n = lat_.n;
    const Rtri roots[2] = {{{0, 0}, {n, n}, {n, 0}}, {{n, n}, {0, 0}, {0, n}}};
    // Visit the current mesh, measuring what was not measured yet and splitting what is
    // over, until a whole pass changes nothing; then one more pass, which changes nothing
    // either (every triangle it meets is measured), emits the result. Emitting in every
    // pass cost as much as the passes themselves.
    for (;;) {
      changed_ = false;
      for (const Rtri& r : roots) visit(r);
      if (failed_) return std::nullopt;
      if (!changed_) break;
    }
    emitting_ = true;
    for (const Rtri& r : roots) visit(r);
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci)
        if (cell_[cell_index(ci, cj)] & kFlipped) {
          for (const Rtri& t : other_halves(ci, cj)) emit_plain(t);
          ++result_.flipped_cells;
        }
    for (const auto& v : result_.tin.vertices) {
      const int i = (static_cast<int>(v.x) - lat_.x0) / lat_.step, j = (static_cast<int>(v.y) - lat_.y0) / lat_.step;
      result_.locked.push_back(locked_[index(i, j)]);
    }
    return std::move(result_);
  }

 private:
  static constexpr std::uint8_t kUnknown = 0, kFits = 1, kOver = 2;
  // Cell flags: each RTIN half measured within the limit; the cell takes the other diagonal.
  static constexpr std::uint8_t kHalfFits[2] = {1, 2};
  static constexpr std::uint8_t kHalfOver[2] = {4, 8};
  static constexpr std::uint8_t kFlipped = 16;

  std::size_t points() const { return static_cast<std::size_t>(lat_.n + 1) * (lat_.n + 1); }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * (lat_.n + 1) + i; }
  std::size_t index(LatticePoint p) const { return index(p.i, p.j); }
  std::size_t cell_index(int ci, int cj) const { return static_cast<std::size_t>(cj) * lat_.n + ci; }
  bool inside(LatticePoint p) const { return p.i >= 0 && p.j >= 0 && p.i <= lat_.n && p.j <= lat_.n; }

  GridPoint point(LatticePoint p) const {
    const int x = lat_.x0 + p.i * lat_.step, y = lat_.y0 + p.j * lat_.step;
    return {double(x), double(y), dem_.sample(x, y)};
  }

  static bool is_leaf(const Rtri& t) { return std::abs(t.a.i - t.c.i) + std::abs(t.a.j - t.c.j) == 1; }
  bool is_root(const Rtri& t) const { return std::abs(t.a.i - t.b.i) == lat_.n && std::abs(t.a.j - t.b.j) == lat_.n; }

  // Which of the two triangles sharing a hypotenuse midpoint: the side of its right angle.
  static int slot(const Rtri& t, LatticePoint m) { return t.c.i != m.i ? (t.c.i > m.i) : (t.c.j > m.j); }

  // The triangle whose split made t. Its hypotenuse midpoint is t's right angle; its right
  // angle is one end of t's hypotenuse, found from the RTIN's alignment: a square of side
  // s at (x0, y0) (multiples of s) is halved by its SW-NE diagonal exactly when
  // x0 / s + y0 / s is even, and the triangles with an axis-aligned hypotenuse of length
  // 2s have their right angle at the centre of such a 2s-square.
  Rtri parent(const Rtri& t) const {
    LatticePoint apex, other;
    if (t.a.i != t.b.i && t.a.j != t.b.j) {  // t is half a square of side s
      const int s = std::abs(t.a.i - t.b.i);
      const bool a_is_centre = (t.a.i / s) % 2 == 1 && (t.a.j / s) % 2 == 1;
      apex = a_is_centre ? t.a : t.b;
      other = a_is_centre ? t.b : t.a;
    } else {  // t's hypotenuse is a side of the 2s-square the parent halves
      const int side = std::abs(t.a.i - t.b.i) + std::abs(t.a.j - t.b.j);
      const LatticePoint fa = reflect(t.a, t.c), fb = reflect(t.b, t.c);
      const int x0 = std::min({t.a.i, t.b.i, fa.i, fb.i}), y0 = std::min({t.a.j, t.b.j, fa.j, fb.j});
      const bool ne = (x0 / side + y0 / side) % 2 == 0;
      auto on_diagonal = [&](LatticePoint p) {
        return ne ? p.i - x0 == p.j - y0 : (p.i - x0) + (p.j - y0) == side;
      };
      apex = on_diagonal(t.a) ? t.b : t.a;
      other = on_diagonal(t.a) ? t.a : t.b;
    }
    return {other, reflect(other, t.c), apex};
  }

  // The triangle across t's hypotenuse (outside the square where that is on the border;
  // a + b - c, not via the midpoint, which is half-integer for the smallest triangles).
  static Rtri partner_of(const Rtri& t) { return {t.b, t.a, {t.a.i + t.b.i - t.c.i, t.a.j + t.b.j - t.c.j}}; }

  // Splits t, its partner and, so that both exist, their ancestors (the closure that
  // keeps the selection conforming).
  void activate(const Rtri& t) {
    const LatticePoint m = midpoint(t.a, t.b);
    std::uint8_t& flag = split_[index(m)];
    if (flag) return;
    flag = 1;
    changed_ = true;
    if (!is_root(t)) activate(parent(t));
    const Rtri partner = partner_of(t);
    if (inside(partner.c) && !is_root(partner)) activate(parent(partner));
  }

  // t counter-clockwise, with every locked point strictly inside its border edges
  // inserted: fans from the opposite corners (transition.hpp's refinement), ids 0..2 = t's
  // corners, 3.. = `extra`.
  void fan(const Rtri& t, std::array<LatticePoint, 3>& corner, std::vector<LatticePoint>& extra,
           std::vector<std::array<int, 3>>& pieces) const {
    corner = {t.a, t.b, t.c};
    if (twice_area(point(t.a), point(t.b), point(t.c)) < 0) std::swap(corner[1], corner[2]);
    extra.clear();
    pieces.clear();
    std::array<EdgeInsert, 3> inserts;
    unsigned sides = 0;
    for (int k = 0; k < 3; ++k) {
      const LatticePoint p = corner[static_cast<std::size_t>(k)], q = corner[static_cast<std::size_t>((k + 1) % 3)];
      int side = -1;
      if (p.i == 0 && q.i == 0) side = kWest;
      else if (p.j == 0 && q.j == 0) side = kSouth;
      else if (p.i == lat_.n && q.i == lat_.n) side = kEast;
      else if (p.j == lat_.n && q.j == lat_.n) side = kNorth;
      if (side < 0) continue;
      const int di = (q.i > p.i) - (q.i < p.i), dj = (q.j > p.j) - (q.j < p.j);
      for (LatticePoint r{p.i + di, p.j + dj}; !(r == q); r = {r.i + di, r.j + dj})
        if (locked_[index(r)]) {
          inserts[static_cast<std::size_t>(k)].points.push_back(3 + static_cast<int>(extra.size()));
          extra.push_back(r);
        }
      if (!inserts[static_cast<std::size_t>(k)].points.empty()) {
        inserts[static_cast<std::size_t>(k)].side = side;
        sides |= 1u << side;
      }
    }
    // Most triangles have no locked point on their edges: the triangle itself, without
    // refine_triangle's work list (an allocation per call).
    if (sides == 0) {
      pieces.push_back({0, 1, 2});
      return;
    }
    refine_triangle({0, 1, 2}, inserts, sides, pieces);
  }

  bool fits(const Rtri& t) {
    std::array<LatticePoint, 3> corner;
    fan(t, corner, extra_, pieces_);
    if (over_at_test_points(corner)) {
      ++result_.rejected;
      return false;
    }
    auto at = [&](int id) { return point(id < 3 ? corner[static_cast<std::size_t>(id)] : extra_[static_cast<std::size_t>(id - 3)]); };
    for (const auto& q : pieces_) {
      ++result_.measured;
      if (measure_(at(q[0]), at(q[1]), at(q[2]), limit_) > limit_) return false;
    }
    return true;
  }

  // A lower bound of the error of the fan's pieces: each piece's plane against the
  // reference at the piece's centroid and edge midpoints. Missing it by more than the limit
  // (with a round-off margin, so that this never rejects what the exact measure would
  // keep) is over, whatever the rest (the base triangulation, with no transition, is one
  // of the variants the measure checks).
  bool over_at_test_points(const std::array<LatticePoint, 3>& corner) const {
    if (!reference_height_) return false;
    auto at = [&](int id) {
      return point(id < 3 ? corner[static_cast<std::size_t>(id)] : extra_[static_cast<std::size_t>(id - 3)]);
    };
    const double margin = limit_ * (1 + 1e-12) + 1e-12;
    auto misses = [&](double x, double y, double z) { return std::abs(z - reference_height_(x, y)) > margin; };
    for (const auto& q : pieces_) {
      const GridPoint a = at(q[0]), b = at(q[1]), c = at(q[2]);
      if (misses((a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3)) return true;
      for (const auto* e : {&a, &b, &c}) {
        const GridPoint& f = e == &a ? b : e == &b ? c : a;
        if (misses(0.5 * (e->x + f.x), 0.5 * (e->y + f.y), 0.5 * (e->z + f.z))) return true;
      }
    }
    return false;
  }

  // The cell's two halves with the diagonal the RTIN does not have (the smallest RTIN
  // triangles halve each 2 x 2 block along the diagonals through its centre: cell
  // (ci, cj) has the SW-NE one exactly when ci + cj is even).
  static std::array<Rtri, 2> other_halves(int ci, int cj) {
    const LatticePoint p00{ci, cj}, p10{ci + 1, cj}, p01{ci, cj + 1}, p11{ci + 1, cj + 1};
    if ((ci + cj) % 2 == 0) return {Rtri{p10, p01, p00}, Rtri{p01, p10, p11}};
    return {Rtri{p00, p11, p10}, Rtri{p11, p00, p01}};
  }

  void visit(const Rtri& t) {
    if (failed_) return;
    const LatticePoint m = midpoint(t.a, t.b);
    if (is_leaf(t)) {
      visit_leaf(t);
      return;
    }
    if (split_[index(m)]) {
      visit({t.c, t.a, m});
      visit({t.b, t.c, m});
      return;
    }
    std::uint8_t& state = state_[2 * index(m) + static_cast<std::size_t>(slot(t, m))];
    if (state == kUnknown) state = fits(t) ? kFits : kOver;
    if (state == kOver) {
      activate(t);
      visit({t.c, t.a, m});
      visit({t.b, t.c, m});
      return;
    }
    emit(t);
  }

  // Half a lattice cell (never split; its edges hold no lattice point). Where it is over
  // the limit the cell takes the other diagonal, which needs the other half's parent split.
  void visit_leaf(const Rtri& t) {
    const int ci = std::min(t.a.i, t.b.i), cj = std::min(t.a.j, t.b.j);
    std::uint8_t& cell = cell_[cell_index(ci, cj)];
    if (cell & kFlipped) return;  // emitted at the end, with the other half
    const int h = t.c.i - ci;
    if (!(cell & (kHalfFits[h] | kHalfOver[h]))) cell |= fits(t) ? kHalfFits[h] : kHalfOver[h];
    if (cell & kHalfFits[h]) {
      emit(t);
      return;
    }
    for (const Rtri& o : other_halves(ci, cj))
      if (!fits(o)) {
        failed_ = true;
        return;
      }
    cell |= kFlipped;
    changed_ = true;
    if (!is_root(t)) activate(parent(partner_of(t)));
  }

  int vertex(LatticePoint p) {
    int& v = vertex_of_[index(p)];
    if (v < 0) {
      v = static_cast<int>(result_.tin.vertices.size());
      result_.tin.vertices.push_back(point(p));
    }
    return v;
  }

  void emit(const Rtri& t) {
    if (!emitting_) return;
    std::array<LatticePoint, 3> corner;
    fan(t, corner, extra_, pieces_);
    for (const auto& q : pieces_) {
      std::array<int, 3> ids{};
      for (int k = 0; k < 3; ++k) {
        const int id = q[static_cast<std::size_t>(k)];
        ids[static_cast<std::size_t>(k)] =
            vertex(id < 3 ? corner[static_cast<std::size_t>(id)] : extra_[static_cast<std::size_t>(id - 3)]);
      }
      result_.tin.triangles.push_back(ids);
    }
  }

  void emit_plain(const Rtri& t) {
    std::array<int, 3> ids{vertex(t.a), vertex(t.b), vertex(t.c)};
    const auto& v = result_.tin.vertices;
    if (twice_area(v[static_cast<std::size_t>(ids[0])], v[static_cast<std::size_t>(ids[1])], v[static_cast<std::size_t>(ids[2])]) < 0)
      std::swap(ids[1], ids[2]);
    result_.tin.triangles.push_back(ids);
  }

  const ReferenceSurface& dem_;
  SquareLattice lat_;
  const std::vector<std::uint8_t>& locked_;
  double limit_;
  const TriangleMeasure& measure_;
  const PointHeight& reference_height_;
  std::vector<std::uint8_t> split_;   // per lattice point: the triangles it bisects are split
  std::vector<std::uint8_t> state_;   // per lattice point x 2 (slot): that triangle's measurement
  std::vector<std::uint8_t> cell_;    // per lattice cell: kHalfFits / kHalfOver / kFlipped
  std::vector<int> vertex_of_;        // per lattice point: vertex id in the result, -1 = none
  std::vector<LatticePoint> extra_;   // scratch of fan()
  std::vector<std::array<int, 3>> pieces_;
  bool changed_ = false, failed_ = false;
  bool emitting_ = false;  // the last pass: emit() writes the result
  RtinStart result_;
};

}  // namespace

std::optional<RtinStart> rtin_start_mesh(const ReferenceSurface& dem, const SquareLattice& lattice,
                                         const std::vector<std::uint8_t>& locked_points, double limit,
                                         const TriangleMeasure& measure, const PointHeight& reference_height) {
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
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i)
      if (locked_points[static_cast<std::size_t>(j) * (n + 1) + i])
        throw usage_error("RTIN start mesh: locked lattice point ({}, {}) is not on the border", i, j);
  RtinBuilder builder(dem, lattice, locked_points, limit, measure, reference_height);
  return builder.run();
}

}  // namespace fest::terrainlod

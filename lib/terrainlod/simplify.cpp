#include "terrainlod/simplify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/mesh.hpp"
#include "terrainlod/collapse_check.hpp"
#include "terrainlod/halfedge_collapse.hpp"
#include "terrainlod/mesh_add_face.hpp"
#include "terrainlod/rtin_start.hpp"

namespace fest::terrainlod {
namespace {

constexpr double kInfinite = std::numeric_limits<double>::infinity();
// Smallest accepted xy area (twice the area, grid units): lattice triangles have at least
// 1, so this only rejects degenerate (collinear) results.
constexpr double kMinTwiceArea = 1e-9;
// Triangles with a bounding box of at most this many cells are measured, not cached.
constexpr double kDirectBoxCells = 32;
// Edges of at most this many cells (|dx| + |dy|) are measured, not cached.
constexpr double kDirectEdgeCells = 4;
// Largest valence of a vertex whose collapse is considered.
constexpr int kMaxFan = 1024;

GridPoint grid_point(const TriMesh& m, TriMesh::VertexHandle v) {
  const auto& p = m.point(v);
  return {p[0], p[1], p[2]};
}

// Open-addressing hash table from a triangle (three vertex ids of 21 bits packed in 64) to
// its error; NaN = not yet known. Disabled for meshes of 2^21 vertices or more. Key and
// value share a slot (one cache miss per probe, not two: the probes were a quarter of the
// engine's own cycles).
class TriangleErrorCache {
 public:
  explicit TriangleErrorCache(std::size_t vertices) : enabled_(vertices < (std::size_t{1} << 21)) {
    if (enabled_) resize(std::size_t{1} << 12);  // grows by doubling; small tiles stay in L2
  }
  bool enabled() const { return enabled_; }
  double* find_or_insert(std::uint64_t key) {
    if (2 * (used_ + 1) > slots_.size()) resize(2 * slots_.size());
    std::size_t i = slot_of(key);
    while (slots_[i].key != kEmpty && slots_[i].key != key) i = (i + 1) & (slots_.size() - 1);
    if (slots_[i].key == kEmpty) {
      slots_[i].key = key;
      slots_[i].value = std::numeric_limits<double>::quiet_NaN();
      ++used_;
    }
    return &slots_[i].value;
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t key = kEmpty;
    double value = 0;
  };
  std::size_t slot_of(std::uint64_t key) const {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return static_cast<std::size_t>(key) & (slots_.size() - 1);
  }
  void resize(std::size_t n) {
    std::vector<Slot> old(n);
    old.swap(slots_);
    used_ = 0;
    for (const Slot& e : old)
      if (e.key != kEmpty) *find_or_insert(e.key) = e.value;
  }
  bool enabled_;
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

// The two references the engine measures against, with one interface: the DEM's grid
// (triangle_error.hpp) and a coarser finished mesh (tin_reference.hpp).
struct GridMeasure {
  const ReferenceSurface& ref;
  double triangle(const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) const {
    return triangle_error(ref, a, b, c, s);
  }
  double samples(const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) const {
    return triangle_samples_error(ref, a, b, c, s);
  }
  double edge(const GridPoint& p, const GridPoint& q, double s) const { return edge_error(ref, p, q, s); }
  double height(const GridPoint& p) const { return p.z; }  // vertices are DEM samples
};

struct TinMeasure {
  const TinReference& ref;
  double triangle(const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) const {
    return ref.triangle_error(a, b, c, s);
  }
  double samples(const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) const {
    return ref.samples_error(a, b, c, s);
  }
  double edge(const GridPoint& p, const GridPoint& q, double s) const { return ref.edge_error(p, q, s); }
  double height(const GridPoint& p) const { return ref.height_at(p.x, p.y); }
};

// transition_error with any reference; the inserted border points are DEM samples (the
// finer neighbours' border vertices).
template <typename Measure>
double transition_error_with(const Measure& measure, const ReferenceSurface& dem, const TileFrame& frame,
                             const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop_above) {
  std::vector<GridPoint> extra;
  const auto inserts = border_inserts(dem, frame, a, b, c, extra);
  unsigned sides = 0;
  for (const auto& e : inserts)
    if (!e.points.empty()) sides |= 1u << e.side;
  double worst = measure.triangle(a, b, c, stop_above);
  if (sides == 0 || worst > stop_above) return worst;
  auto point = [&](int id) -> const GridPoint& { return id == 0 ? a : id == 1 ? b : id == 2 ? c : extra[id - 3]; };
  std::vector<std::array<int, 3>> pieces;
  for (unsigned m = 1; m < 16; ++m) {
    if ((m & sides) != m) continue;  // every non-empty subset of the triangle's refinable sides
    pieces.clear();
    refine_triangle({0, 1, 2}, inserts, m, pieces);
    for (const auto& t : pieces) {
      worst = std::max(worst, measure.triangle(point(t[0]), point(t[1]), point(t[2]), stop_above));
      if (worst > stop_above) return worst;
    }
  }
  return worst;
}

// The order of the elements OpenMesh's ArrayKernel::garbage_collection keeps: from both
// ends, the first deleted element swaps places with the last live one until they meet.
// Returns the old indices of the live elements in their new order.
std::vector<int> compaction_order(std::vector<std::uint8_t> deleted) {
  const int n = static_cast<int>(deleted.size());
  std::vector<int> order(deleted.size());
  for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  if (n == 0) return order;
  int i0 = 0, i1 = n - 1;
  for (;;) {
    while (!deleted[static_cast<std::size_t>(i0)] && i0 < i1) ++i0;
    while (deleted[static_cast<std::size_t>(i1)] && i0 < i1) --i1;
    if (i0 >= i1) break;
    std::swap(deleted[static_cast<std::size_t>(i0)], deleted[static_cast<std::size_t>(i1)]);
    std::swap(order[static_cast<std::size_t>(i0)], order[static_cast<std::size_t>(i1)]);
  }
  order.resize(static_cast<std::size_t>(deleted[static_cast<std::size_t>(i0)] ? i0 : i0 + 1));
  return order;
}

template <typename Measure>
class CollapseEngine {
 public:
  CollapseEngine(Measure measure, const ReferenceSurface& dem, const Tin& start, const std::vector<std::uint8_t>& locked,
                 double limit, const TileFrame* frame)
      : measure_(measure), dem_(dem), limit_(limit), frame_(frame), cache_(start.vertices.size()),
        edge_cache_(start.vertices.size()) {
    build(start, locked);
    zref_.reserve(start.vertices.size());
    for (const auto& p : start.vertices) zref_.push_back(measure_.height(p));
  }

  // `progress` (may be empty): thousandths of the bound reached by the collapse costs.
  SimplifyResult run(const ProgressFn& progress = {}) {
    SimplifyResult result;
    for (auto v : m_.vertices()) refresh(v);
    std::uint64_t reported = 0;
    while (!heap_.empty()) {
      const auto [cost, vi, wi, version] = heap_.top();
      heap_.pop();
      const auto v = TriMesh::VertexHandle(vi);
      if (removed_[vi] || version != version_[vi]) continue;
      if (dirty_[vi]) {  // its star changed since the entry was made: measure again first
        refresh(v);
        continue;
      }
      const auto w = TriMesh::VertexHandle(wi);
      const auto heh = halfedge_to(v, w);
      // The link condition can change without v's star changing (a collapse next to w);
      // the error of the collapse cannot, as it depends on v's star and w's position only.
      if (!heh.is_valid() || !check_.collapse_ok(m_, heh)) {
        refresh(v);
        continue;
      }
      // Only the stars of v's neighbours change (v becomes w in them); w's other
      // neighbours keep their stars and so their costs (a link condition that changes
      // for them is caught when their entry is popped). The neighbours are re-measured
      // lazily, when their entry comes up: many are changed again before that.
      ring_.clear();
      for (auto u : m_.vv_range(v)) ring_.push_back(u);
      collapse_halfedge(m_, heh);  // = m_.collapse(heh), without the library's out-of-line checks
      removed_[vi] = 1;
      ++result.collapses;
      result.max_error = std::max(result.max_error, cost);
      for (auto u : ring_) mark_dirty(u);
      if (progress && (result.collapses & 4095) == 0 && limit_ > 0) {
        const auto at = static_cast<std::uint64_t>(1000 * std::min(1.0, result.max_error / limit_));
        if (at > reported) progress(reported = at, 1000);
      }
    }
    // The result in the order OpenMesh's garbage_collection() leaves the mesh in, without
    // running it (the library is built with its assertions, whose property checks compare
    // type names: 5 % of a pyramid build went there).
    std::vector<std::uint8_t> gone(m_.n_vertices());
    for (std::size_t i = 0; i < gone.size(); ++i) gone[i] = m_.status(TriMesh::VertexHandle(static_cast<int>(i))).deleted();
    const std::vector<int> vorder = compaction_order(gone);
    gone.assign(m_.n_faces(), 0);
    for (std::size_t i = 0; i < gone.size(); ++i) gone[i] = m_.status(TriMesh::FaceHandle(static_cast<int>(i))).deleted();
    const std::vector<int> forder = compaction_order(gone);
    std::vector<int> new_id(m_.n_vertices(), -1);
    for (std::size_t k = 0; k < vorder.size(); ++k) {
      new_id[static_cast<std::size_t>(vorder[k])] = static_cast<int>(k);
      result.mesh.vertices.push_back(grid_point(m_, TriMesh::VertexHandle(vorder[k])));
    }
    for (int fi : forder) {
      std::array<int, 3> t{};
      int k = 0;
      for (auto v : m_.fv_range(TriMesh::FaceHandle(fi))) t[k++] = new_id[static_cast<std::size_t>(v.idx())];
      result.mesh.triangles.push_back(t);
    }
    return result;
  }

 private:
  void build(const Tin& start, const std::vector<std::uint8_t>& locked) {
    m_.request_vertex_status();
    m_.request_edge_status();
    m_.request_face_status();
    // A disc: edges = vertices + faces - 1 (Euler); reserved so that adding grows nothing.
    m_.reserve(start.vertices.size(), start.vertices.size() + start.triangles.size(), start.triangles.size());
    for (const auto& p : start.vertices) m_.add_vertex(TriMesh::Point(p.x, p.y, p.z));
    // add_triangle = m_.add_face, without the library's out-of-line checks (mesh_add_face.hpp).
    for (const auto& t : start.triangles)
      add_triangle(m_, TriMesh::VertexHandle(t[0]), TriMesh::VertexHandle(t[1]), TriMesh::VertexHandle(t[2]));
    locked_ = locked;
    check_ = CollapseCheck(m_.n_vertices());
    version_.assign(m_.n_vertices(), 0);
    dirty_.assign(m_.n_vertices(), 0);
    live_.assign(m_.n_vertices(), 0);
    removed_.assign(m_.n_vertices(), 0);
  }

  // The half-edge v -> w, or an invalid one: m_.find_halfedge, circulating with the
  // header's inline accessors instead of the assertion-built library's.
  TriMesh::HalfedgeHandle halfedge_to(TriMesh::VertexHandle v, TriMesh::VertexHandle w) const {
    for (auto h : m_.voh_range(v))
      if (m_.to_vertex_handle(h) == w) return h;
    return TriMesh::HalfedgeHandle();
  }

  double measure(const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop) const {
    return frame_ ? transition_error_with(measure_, dem_, *frame_, a, b, c, stop) : measure_.triangle(a, b, c, stop);
  }

  // Error of collapsing v onto w; kInfinite when not allowed, above the bound, or above
  // `stop` (<= the bound: a candidate worse than the best one found so far need not be
  // measured to the end).
  double collapse_cost(TriMesh::HalfedgeHandle heh, double stop) {  // non-const: the link check keeps marks
    const auto w = m_.to_vertex_handle(heh);
    // Border vertices slide along their border only: the edge must be a border edge.
    if (star_boundary_ && !m_.is_boundary(m_.edge_handle(heh))) return kInfinite;
    const GridPoint pw = grid_point(m_, w);
    const GridPoint& pv = star_pv_;
    // First the new triangles' shapes and a cheap lower bound of the error: the removed
    // sample v lies in one of them, and the new surface must pass within the bound of it.
    // Most rejected candidates fail here, before any scan.
    const int vi = star_vi_, wi = w.idx();
    const double zv = zref_[static_cast<std::size_t>(vi)];
    // The bound is tested on the star's own corners with w in v's place (no copy): most
    // candidates fail it, and copying every new triangle first was a tenth of the engine's
    // instructions. The same expressions on the same doubles as on the copies.
    for (const StarFace& sf : star_) {  // v's faces in OpenMesh's order (vf_range)
      if (sf.id[sf.next] == wi || sf.id[sf.prev] == wi) continue;  // the two triangles on edge v-w disappear
      const GridPoint* c[3] = {&sf.p[0], &sf.p[1], &sf.p[2]};
      c[sf.at_v] = &pw;
      const GridPoint &c0 = *c[0], &c1 = *c[1], &c2 = *c[2];
      const double d = twice_area(c0, c1, c2);
      if (d < kMinTwiceArea) return kInfinite;  // fold-over
      const double wa = twice_area(pv, c1, c2), wb = twice_area(c0, pv, c2), wc = twice_area(c0, c1, pv);
      if (wa >= 0 && wb >= 0 && wc >= 0 && std::abs((wa * c0.z + wb * c1.z + wc * c2.z) / d - zv) > stop)
        return kInfinite;
    }
    // Passed: the new triangles into the member buffer `fan_` (sized for the star in
    // refresh()).
    int n = 0;
    for (const StarFace& sf : star_) {
      if (sf.id[sf.next] == wi || sf.id[sf.prev] == wi) continue;
      if (n == kMaxFan) return kInfinite;  // a vertex of absurd valence stays (never seen on grids)
      NewTriangle& t = fan_[static_cast<std::size_t>(n)];
      for (int k = 0; k < 3; ++k) {
        t.corner[k] = sf.p[k];
        t.id[k] = static_cast<std::uint64_t>(sf.id[k]);
      }
      t.corner[sf.at_v] = pw;
      t.id[sf.at_v] = static_cast<std::uint64_t>(wi);
      ++n;
    }
    // Triangle by triangle, the samples first, then the edges: this order decides which
    // long edges and large triangles are measured first, and in which orientation the
    // tables remember them (the walks differ in the last bit by direction), so it is part
    // of the result. Measuring all the fan's edges before any samples saved 5 % of the
    // instructions but changed the 1 m mesh of the Jacksboro crop (same counts and error).
    auto& fan = fan_;
    double worst = 0;
    for (int t = 0; t < n; ++t) {
      worst = std::max(worst, cached_error(fan[t].id, fan[t].corner, stop));
      if (worst > stop) return kInfinite;
    }
    if (!check_.collapse_ok(m_, heh)) return kInfinite;
    return worst;
  }

  // Error of the triangle `corner` (face f with v replaced by w). A triangle's error
  // depends only on its three vertices, which never move, so the same candidate triangles
  // and edges that come back every time a neighbourhood is re-examined need not be measured
  // again: the error is the larger of the samples inside (remembered per triangle) and the
  // crossings along the three edges (remembered per edge: an edge is shared by two
  // triangles of a fan, and the link edges of v by every candidate of v).
  double cached_error(const std::uint64_t (&id)[3], const GridPoint (&corner)[3], double stop) {
    // Triangles with a transition variant are measured whole (transition_error).
    const bool whole = frame_ && on_refinable_border(corner);
    double e = triangle_part(id, corner, stop, whole);
    if (whole || e > stop) return e;
    for (int a = 0; a < 3; ++a) {
      e = std::max(e, cached_edge_error(id[a], id[(a + 1) % 3], corner[a], corner[(a + 1) % 3]));
      if (e > stop) return kInfinite;
    }
    return e;
  }

  bool on_refinable_border(const GridPoint (&c)[3]) const {
    const TileFrame& fr = *frame_;
    if (fr.fine_step <= 0) return false;
    for (int a = 0; a < 3; ++a) {
      const GridPoint &p = c[a], &q = c[(a + 1) % 3];
      if ((p.x == fr.x0 && q.x == fr.x0 && (fr.refinable & (1u << kWest))) ||
          (p.y == fr.y0 && q.y == fr.y0 && (fr.refinable & (1u << kSouth))) ||
          (p.x == fr.x1 && q.x == fr.x1 && (fr.refinable & (1u << kEast))) ||
          (p.y == fr.y1 && q.y == fr.y1 && (fr.refinable & (1u << kNorth))))
        return true;
    }
    return false;
  }

  // The samples part of a triangle's error (or, `whole`, all of it with its transition
  // variants), remembered for triangles whose box spans many cells: small ones are cheaper
  // to measure again than to look up in a large table (a cache miss).
  double triangle_part(const std::uint64_t (&vid)[3], const GridPoint (&corner)[3], double stop, bool whole) {
    auto measure_part = [&](double s) {
      return whole ? measure(corner[0], corner[1], corner[2], s)
                   : measure_.samples(corner[0], corner[1], corner[2], s);
    };
    const double box = (std::max({corner[0].x, corner[1].x, corner[2].x}) - std::min({corner[0].x, corner[1].x, corner[2].x})) *
                       (std::max({corner[0].y, corner[1].y, corner[2].y}) - std::min({corner[0].y, corner[1].y, corner[2].y}));
    if (!cache_.enabled() || box <= kDirectBoxCells) return clamp_error(measure_part(stop));
    std::uint64_t id[3] = {vid[0], vid[1], vid[2]};
    if (id[0] > id[1]) std::swap(id[0], id[1]);
    if (id[1] > id[2]) std::swap(id[1], id[2]);
    if (id[0] > id[1]) std::swap(id[0], id[1]);
    const std::uint64_t key = (id[0] << 42) | (id[1] << 21) | id[2];
    double* slot = cache_.find_or_insert(key);
    if (!std::isnan(*slot)) return *slot;
    const double e = measure_part(stop);
    // Stopped early below the bound: e is only a lower bound, not worth remembering.
    if (e > stop && stop < limit_) return kInfinite;
    *slot = clamp_error(e);
    return *slot;
  }

  // Crossings of edge (p, q) with the reference, measured to the end once (an edge's
  // error is needed exactly by every triangle that has it).
  // Within one refresh() the same edges come back many times: v's link edges in every
  // candidate's fan, each spoke w-u in two triangles of it. They are remembered in a short
  // list for the current vertex first (no walk, no probe of the large table). A walk from
  // p to q can differ from q to p in the last bit, so edges that are measured directly
  // are remembered per direction (as if measured again); the table's edges are one value
  // for both directions (the first measured), as in the table.
  double cached_edge_error(std::uint64_t a, std::uint64_t b, const GridPoint& p, const GridPoint& q) {
    const bool direct = std::abs(p.x - q.x) + std::abs(p.y - q.y) <= kDirectEdgeCells || !edge_cache_.enabled();
    if (!direct && a > b) std::swap(a, b);
    const std::uint64_t key = (a << 32) | b;
    std::size_t i = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> 57);  // 7 bits
    for (; memo_[i].stamp == memo_stamp_; i = (i + 1) & (kMemoSlots - 1))
      if (memo_[i].key == key) return memo_[i].error;
    double e;
    if (direct) {
      e = measure_.edge(p, q, kInfinite);
    } else {
      double* slot = edge_cache_.find_or_insert(key);
      if (std::isnan(*slot)) *slot = measure_.edge(p, q, kInfinite);
      e = *slot;
    }
    if (memo_used_ < kMemoSlots / 2) {  // a full list only stops remembering
      memo_[i] = {key, e, memo_stamp_};
      ++memo_used_;
    }
    return e;
  }

  // An early stop is only a lower bound of the error: remember it as "too big".
  double clamp_error(double e) const { return e > limit_ ? kInfinite : e; }

  // A vertex whose star changed: its queue entry keeps its place but is re-measured when
  // popped. A vertex without an entry (no collapse was possible) gets one at cost 0, so it
  // is re-measured next.
  void mark_dirty(TriMesh::VertexHandle u) {
    const int ui = u.idx();
    if (locked_[ui]) return;
    dirty_[ui] = 1;
    if (!live_[ui]) {
      heap_.push({0.0, ui, -1, version_[ui]});
      live_[ui] = 1;
    }
  }

  // Recomputes v's cheapest collapse and queues it; older queue entries go stale.
  void refresh(TriMesh::VertexHandle v) {
    const int vi = v.idx();
    ++version_[vi];
    dirty_[vi] = 0;
    live_[vi] = 0;
    if (locked_[vi]) return;
    if (++memo_stamp_ == 0) {  // wrapped: clear the stamps once
      for (auto& m : memo_) m.stamp = 0;
      memo_stamp_ = 1;
    }
    memo_used_ = 0;
    // v's star for every candidate of this refresh (it does not change meanwhile).
    // Written in place (no zeroed local copied in), corners through the face's half-edges.
    static constexpr int kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
    star_.clear();
    for (auto f : m_.vf_range(v)) {
      star_.emplace_back();
      StarFace& sf = star_.back();
      // The corners in m_.fv_range(f)'s order (from the face's half-edge along next),
      // without the circulator's lap bookkeeping.
      auto h = m_.halfedge_handle(f);
      for (int k = 0; k < 3; ++k, h = m_.next_halfedge_handle(h)) {
        const auto u = m_.to_vertex_handle(h);
        if (u == v) sf.at_v = k;
        sf.id[k] = u.idx();
        sf.p[k] = grid_point(m_, u);
      }
      sf.next = kNext[sf.at_v];
      sf.prev = kPrev[sf.at_v];
    }
    if (fan_.size() < star_.size()) fan_.resize(star_.size());
    star_vi_ = vi;
    star_pv_ = grid_point(m_, v);
    star_boundary_ = m_.is_boundary(v);
    double best = kInfinite;
    int target = -1;
    for (auto heh : m_.voh_range(v)) {
      const double c = collapse_cost(heh, std::min(best, limit_));
      const int ti = m_.to_vertex_handle(heh).idx();
      if (c < best || (c == best && c < kInfinite && ti < target)) {
        best = c;
        target = ti;
      }
    }
    if (target >= 0) {
      heap_.push({best, vi, target, version_[vi]});
      live_[vi] = 1;
    }
  }

  struct NewTriangle {
    std::uint64_t id[3];  // vertex ids (v replaced by w)
    GridPoint corner[3];
  };
  std::vector<NewTriangle> fan_;  // scratch of collapse_cost
  struct StarFace {
    int id[3];
    GridPoint p[3];
    int at_v = 0, next = 1, prev = 2;  // v's corner and the two others
  };
  std::vector<StarFace> star_;  // the refreshed vertex's faces, corners in face order
  int star_vi_ = -1;            // the refreshed vertex, its point, and whether it is on the boundary
  GridPoint star_pv_;
  bool star_boundary_ = false;
  // Edge errors met in this refresh(): a small open-addressing table, cleared by stamp.
  struct MemoSlot {
    std::uint64_t key = 0;
    double error = 0;
    std::uint32_t stamp = 0;
  };
  static constexpr std::size_t kMemoSlots = 128;
  std::array<MemoSlot, kMemoSlots> memo_{};
  std::uint32_t memo_stamp_ = 0;
  std::size_t memo_used_ = 0;
  // Queue entry: cost, v, w, version, popped smallest first in this lexicographic order
  // (that of the std::tuple it replaces; the order is total, so any correct heap pops the
  // same sequence). A plain struct with its own comparison: the tuple's generic operator<
  // was a twentieth of the engine's instructions.
  struct Entry {
    double cost;
    int v, w;
    std::uint32_t version;
  };
  struct Later {  // a comes out after b (std::greater on the tuple, written out)
    bool operator()(const Entry& a, const Entry& b) const {
      if (b.cost < a.cost) return true;
      if (a.cost < b.cost) return false;
      if (a.v != b.v) return a.v > b.v;
      if (a.w != b.w) return a.w > b.w;
      return a.version > b.version;
    }
  };
  Measure measure_;
  const ReferenceSurface& dem_;
  std::vector<double> zref_;  // the reference's height at every vertex (lower bounds)
  double limit_;
  const TileFrame* frame_;
  TriMesh m_;
  std::vector<std::uint8_t> locked_;
  std::vector<std::uint32_t> version_;
  std::vector<std::uint8_t> dirty_;  // star changed since the last measurement
  std::vector<std::uint8_t> live_;   // has a queue entry of the current version
  // Collapsed away (OpenMesh's status flag, without its status() accessor's lookup by name).
  std::vector<std::uint8_t> removed_;
  std::priority_queue<Entry, std::vector<Entry>, Later> heap_;
  TriangleErrorCache cache_;       // per triangle (three vertex ids)
  TriangleErrorCache edge_cache_;  // per edge (two vertex ids)
  std::vector<TriMesh::VertexHandle> ring_;
  CollapseCheck check_{0};
};

}  // namespace

Tin finest_triangulation(const HeightGrid& grid, DiagonalRule diagonal) {
  Tin tin;
  tin.vertices.reserve(grid.size());
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) tin.vertices.push_back({double(i), double(j), grid.at(i, j)});
  const ReferenceSurface ref(grid, diagonal);
  const int w = grid.width;
  for (int j = 0; j + 1 < grid.height; ++j)
    for (int i = 0; i + 1 < w; ++i) {
      const int a = j * w + i, b = a + 1, c = a + w, d = a + w + 1;
      if (ref.ne_diagonal(i, j)) {
        tin.triangles.push_back({a, b, d});
        tin.triangles.push_back({a, d, c});
      } else {
        tin.triangles.push_back({a, b, c});
        tin.triangles.push_back({b, d, c});
      }
    }
  return tin;
}

SimplifyResult simplify_grid(const HeightGrid& grid, const SimplifyOptions& options) {
  if (!(options.max_error >= 0) || !std::isfinite(options.max_error))
    throw usage_error("error bound must be a finite number >= 0 (got {})", options.max_error);
  double lo = grid.h.empty() ? 0 : grid.h[0], hi = lo;
  for (double z : grid.h) lo = std::min(lo, z), hi = std::max(hi, z);
  const double tolerance = 1e-9 * std::max(1.0, hi - lo);
  const ReferenceSurface ref(grid, options.diagonal);
  const double limit = options.max_error + tolerance;
  const int w = grid.width;
  // A square grid of 2^k + 1 samples starts from the RTIN within the bound (four corners
  // locked: the rest of the border slides, as from the lattice).
  const int n = w - 1;
  if (options.start == StartRule::rtin && grid.height == w && n >= 1 && (n & (n - 1)) == 0) {
    std::vector<std::uint8_t> corners(grid.size(), 0);
    for (int c : {0, w - 1, (grid.height - 1) * w, grid.height * w - 1}) corners[static_cast<std::size_t>(c)] = 1;
    const TriangleMeasure measure = [&ref](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
      return triangle_error(ref, a, b, c, s);
    };
    // Every lattice cell fits with the reference's own diagonal, so there is always a
    // start mesh; the fallback below only guards the contract. No lower-bound screen
    // (rtin_start_mesh's reference_height): against the grid the exact measure stops at
    // the first sample over the limit, and the screen's point look-ups cost more than
    // they saved (Jacksboro 257^2 at 10 m: 192 M -> 162 M instructions without; the same
    // mesh, as the screen only rejects what the measure would).
    if (auto rtin = rtin_start_mesh(ref, SquareLattice{0, 0, n, 1}, corners, limit, measure)) {
      CollapseEngine<GridMeasure> engine(GridMeasure{ref}, ref, rtin->tin, rtin->locked, limit, nullptr);
      SimplifyResult result = engine.run(options.progress);
      result.tolerance = tolerance;
      return result;
    }
  }
  const Tin start = finest_triangulation(grid, options.diagonal);
  std::vector<std::uint8_t> locked(start.vertices.size(), 0);
  for (int c : {0, w - 1, (grid.height - 1) * w, grid.height * w - 1}) locked[static_cast<std::size_t>(c)] = 1;
  CollapseEngine<GridMeasure> engine(GridMeasure{ref}, ref, start, locked, limit, nullptr);
  SimplifyResult result = engine.run(options.progress);
  result.tolerance = tolerance;
  return result;
}

SimplifyResult simplify_tin(const ReferenceSurface& ref, const Tin& start, const std::vector<std::uint8_t>& locked,
                            double limit, const TileFrame* frame) {
  CollapseEngine<GridMeasure> engine(GridMeasure{ref}, ref, start, locked, limit, frame);
  return engine.run();
}

SimplifyResult simplify_tin(const TinReference& ref, const ReferenceSurface& dem, const Tin& start,
                            const std::vector<std::uint8_t>& locked, double limit, const TileFrame* frame) {
  CollapseEngine<TinMeasure> engine(TinMeasure{ref}, dem, start, locked, limit, frame);
  return engine.run();
}

std::array<EdgeInsert, 3> border_inserts(const ReferenceSurface& ref, const TileFrame& frame, const GridPoint& a,
                                         const GridPoint& b, const GridPoint& c, std::vector<GridPoint>& points) {
  std::array<EdgeInsert, 3> inserts;
  if (frame.fine_step <= 0) return inserts;
  const GridPoint* v[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const GridPoint &p = *v[k], &q = *v[(k + 1) % 3];
    int side = -1;
    if (p.x == frame.x0 && q.x == frame.x0) side = kWest;
    else if (p.y == frame.y0 && q.y == frame.y0) side = kSouth;
    else if (p.x == frame.x1 && q.x == frame.x1) side = kEast;
    else if (p.y == frame.y1 && q.y == frame.y1) side = kNorth;
    if (side < 0 || !(frame.refinable & (1u << side))) continue;
    inserts[k].side = side;
    // Lattice points strictly between p and q, in order from p.
    const bool vertical = side == kWest || side == kEast;
    const int from = static_cast<int>(vertical ? p.y : p.x), to = static_cast<int>(vertical ? q.y : q.x);
    const int step = to > from ? frame.fine_step : -frame.fine_step;
    for (int s = from + step; step > 0 ? s < to : s > to; s += step) {
      const int x = vertical ? static_cast<int>(p.x) : s, y = vertical ? s : static_cast<int>(p.y);
      inserts[k].points.push_back(static_cast<int>(points.size()) + 3);
      points.push_back({double(x), double(y), ref.sample(x, y)});
    }
  }
  return inserts;
}

double transition_error(const ReferenceSurface& ref, const TileFrame& frame, const GridPoint& a,
                        const GridPoint& b, const GridPoint& c, double stop_above) {
  return transition_error_with(GridMeasure{ref}, ref, frame, a, b, c, stop_above);
}

double transition_error(const TinReference& ref, const ReferenceSurface& dem, const TileFrame& frame,
                        const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop_above) {
  return transition_error_with(TinMeasure{ref}, dem, frame, a, b, c, stop_above);
}

double tin_error(const ReferenceSurface& reference, const Tin& tin) {
  double worst = 0;
  for (const auto& t : tin.triangles)
    worst = std::max(worst, triangle_error(reference, tin.vertices[t[0]], tin.vertices[t[1]], tin.vertices[t[2]],
                                           kInfinite));
  return worst;
}

}  // namespace fest::terrainlod

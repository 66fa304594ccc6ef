// Adaptive extraction: docs/isosurf.md "Adaptive mode" (selection 2.4, closure loop,
// transition faces 2.5).
#include "isosurface/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/parallel_for.hpp"

namespace fest::isosurface {
namespace {

using volume_pyramid::MinMaxPyramid;
using volume_pyramid::ScalarGrid;
using Key = std::uint64_t;

struct LeafLoops {
  std::vector<Key> keys;             // loops one after another
  std::vector<std::uint8_t> masks;   // per vertex: faces of the leaf it lies on
  std::vector<std::uint32_t> lengths;
};

class Adaptive {
 public:
  Adaptive(const ScalarGrid& g, float iso, const AdaptiveOptions& o, const MinMaxPyramid& p) : g_(g), iso_(iso), o_(o), pyr_(p) {
    for (int a = 0; a < 3; ++a) n_[a] = g.dims[a], cn_[a] = g.dims[a] - 1;
    const std::size_t longest = std::max({cn_[0], cn_[1], cn_[2]});
    root_ = 0;
    while ((std::size_t{1} << root_) < longest) ++root_;
    max_level_ = o.max_level < 0 ? root_ : std::min(o.max_level, root_);
    r0_ = o.focus_radius;
    if (!(r0_ > 0)) {
      const auto a = g.world(0, 0, 0), b = g.world(double(cn_[0]), double(cn_[1]), double(cn_[2]));
      r0_ = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])) / 32;
    }
  }

  AdaptiveResult run() {
    AdaptiveResult r;
    select(r);
    rebuild_levels();
    // The closure loop. A leaf's verdict depends only on the levels of the cells in its box
    // and the one-cell shell around it, and levels only change where a leaf is split; so a
    // leaf found fine stays fine until a split touches an 8^3 block under its shell, and
    // only such leaves (and new ones) are examined again. Same result as examining all.
    std::vector<char> ok(leaves_.size(), 0);
    for (int a = 0; a < 3; ++a) db_[a] = (cn_[a] + 7) / 8;
    dirty_.assign(db_[0] * db_[1] * db_[2], 0);
    for (bool changed = true; changed;) {
      changed = false;
      std::vector<Leaf> next, split, fresh;
      std::vector<char> next_ok;
      next.reserve(leaves_.size());
      next_ok.reserve(leaves_.size());
      for (std::size_t x = 0; x < leaves_.size(); ++x) {
        const Leaf& L = leaves_[x];
        const bool fine = L.level == 0 || (ok[x] && !shell_dirty(L)) || !(unbalanced(L) || !edges_consistent(L));
        if (!fine) {
          changed = true;
          ++r.closure_splits;
          split.push_back(L);
          const std::size_t before = next.size();
          push_active_children(L, next);
          fresh.insert(fresh.end(), next.begin() + std::ptrdiff_t(before), next.end());
          next_ok.resize(next.size(), 0);
        } else {
          next.push_back(L);
          next_ok.push_back(1);
        }
      }
      leaves_.swap(next);
      ok.swap(next_ok);
      std::fill(dirty_.begin(), dirty_.end(), 0);
      for (const Leaf& L : split) mark(L, -1), mark_dirty(L);
      for (const Leaf& L : fresh) mark(L, static_cast<std::int8_t>(L.level));
    }
    std::sort(leaves_.begin(), leaves_.end(), [](const Leaf& a, const Leaf& b) {
      const std::uint64_t ka = std::uint64_t{a.k} << a.level, kb = std::uint64_t{b.k} << b.level;
      const std::uint64_t ja = std::uint64_t{a.j} << a.level, jb = std::uint64_t{b.j} << b.level;
      const std::uint64_t ia = std::uint64_t{a.i} << a.level, ib = std::uint64_t{b.i} << b.level;
      return std::tie(ka, ja, ia, a.level) < std::tie(kb, jb, ib, b.level);
    });
    r.leaves_per_level.assign(static_cast<std::size_t>(root_) + 1, 0);
    for (const Leaf& L : leaves_) ++r.leaves_per_level[L.level];
    triangulate(r);
    r.leaves = leaves_;
    r.max_error_bound = max_error_bound_;
    return r;
  }

 private:
  bool in(std::size_t i, std::size_t j, std::size_t k) const { return g_.at(i, j, k) >= iso_; }
  std::size_t S(const Leaf& L) const { return std::size_t{1} << L.level; }
  void box(const Leaf& L, std::size_t lo[3], std::size_t hi[3]) const {
    const std::size_t s = S(L), idx[3] = {L.i, L.j, L.k};
    for (int a = 0; a < 3; ++a) lo[a] = idx[a] * s, hi[a] = std::min(lo[a] + s, n_[a] - 1);
  }
  bool inside_domain(const Leaf& L) const {
    const std::size_t s = S(L), idx[3] = {L.i, L.j, L.k};
    for (int a = 0; a < 3; ++a)
      if ((idx[a] + 1) * s > cn_[a]) return false;
    return true;
  }
  bool active(const Leaf& L) const {
    float mn, mx;
    if (L.level >= pyr_.finest_level()) {
      mn = pyr_.min(L.level, L.i, L.j, L.k), mx = pyr_.max(L.level, L.i, L.j, L.k);
    } else {
      std::size_t lo[3], hi[3];
      box(L, lo, hi);
      mn = std::numeric_limits<float>::infinity(), mx = -mn;
      for (std::size_t k = lo[2]; k <= hi[2]; ++k)
        for (std::size_t j = lo[1]; j <= hi[1]; ++j)
          for (std::size_t i = lo[0]; i <= hi[0]; ++i) mn = std::min(mn, g_.at(i, j, k)), mx = std::max(mx, g_.at(i, j, k));
    }
    return mn < iso_ && iso_ <= mx;
  }
  double distance(const Leaf& L) const {
    if (!o_.focus) return 0;
    std::size_t lo[3], hi[3];
    box(L, lo, hi);
    double bmin[3] = {INFINITY, INFINITY, INFINITY}, bmax[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < 8; ++c) {
      const auto w = g_.world(double(c & 1 ? hi[0] : lo[0]), double(c & 2 ? hi[1] : lo[1]), double(c & 4 ? hi[2] : lo[2]));
      for (int a = 0; a < 3; ++a) bmin[a] = std::min(bmin[a], w[a]), bmax[a] = std::max(bmax[a], w[a]);
    }
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
      const double f = (*o_.focus)[a], e = f < bmin[a] ? bmin[a] - f : f > bmax[a] ? f - bmax[a] : 0.0;
      d2 += e * e;
    }
    return std::sqrt(d2);
  }
  // eps(n): largest deviation of the samples of the node from the trilinear interpolant of
  // its 8 corners.
  double error(const Leaf& L) const {
    std::size_t lo[3], hi[3];
    box(L, lo, hi);
    const double s = double(S(L));
    double c[8];
    for (int q = 0; q < 8; ++q) c[q] = g_.at(q & 1 ? hi[0] : lo[0], q & 2 ? hi[1] : lo[1], q & 4 ? hi[2] : lo[2]);
    double e = 0;
    for (std::size_t k = lo[2]; k <= hi[2]; ++k)
      for (std::size_t j = lo[1]; j <= hi[1]; ++j)
        for (std::size_t i = lo[0]; i <= hi[0]; ++i) {
          const double x = (i - lo[0]) / s, y = (j - lo[1]) / s, z = (k - lo[2]) / s;
          const double t = (1 - z) * ((1 - y) * ((1 - x) * c[0] + x * c[1]) + y * ((1 - x) * c[2] + x * c[3])) +
                           z * ((1 - y) * ((1 - x) * c[4] + x * c[5]) + y * ((1 - x) * c[6] + x * c[7]));
          e = std::max(e, std::abs(g_.at(i, j, k) - t));
        }
    return e;
  }

  void children(const Leaf& L, std::vector<Leaf>& out) const {
    const std::uint8_t l = static_cast<std::uint8_t>(L.level - 1);
    const std::size_t s = std::size_t{1} << l;
    for (int c = 0; c < 8; ++c) {
      const Leaf ch{l, 2 * L.i + (c & 1), 2 * L.j + (c >> 1 & 1), 2 * L.k + (c >> 2 & 1)};
      if (ch.i * s >= cn_[0] || ch.j * s >= cn_[1] || ch.k * s >= cn_[2]) continue;
      out.push_back(ch);
    }
  }
  void push_active_children(const Leaf& L, std::vector<Leaf>& out) const {
    std::vector<Leaf> ch;
    children(L, ch);
    for (const Leaf& c : ch)
      if (active(c)) out.push_back(c);
  }

  // Selection (2.4): from the root, split active nodes that are too coarse for their
  // distance to the focus, too far from trilinear, or not inside the domain.
  void select(AdaptiveResult&) {
    std::vector<Leaf> stack{Leaf{static_cast<std::uint8_t>(root_), 0, 0, 0}};
    const bool use_error = std::isfinite(o_.max_error);
    while (!stack.empty()) {
      const Leaf L = stack.back();
      stack.pop_back();
      if (!active(L)) continue;
      if (L.level == 0) {
        leaves_.push_back(L);
        continue;
      }
      const double d = distance(L);
      const int allowed = o_.focus ? static_cast<int>(std::floor(std::log2(1 + d / r0_))) : root_;
      bool split = !inside_domain(L) || L.level > std::min(allowed, max_level_);
      if (!split && use_error) {
        const double e = error(L);
        split = e > o_.max_error * std::pow(1 + d / r0_, o_.error_growth);
        if (!split) max_error_bound_ = std::max(max_error_bound_, e);
      }
      if (split) {
        std::vector<Leaf> ch;
        children(L, ch);
        for (auto it = ch.rbegin(); it != ch.rend(); ++it) stack.push_back(*it);
      } else {
        leaves_.push_back(L);
      }
    }
  }

  std::size_t cell(std::size_t i, std::size_t j, std::size_t k) const { return i + cn_[0] * (j + cn_[1] * k); }
  // Sets the level of every cell of L's box.
  void mark(const Leaf& L, std::int8_t level) {
    const std::size_t s = S(L);
    for (std::size_t k = L.k * s; k < std::min((L.k + 1) * s, cn_[2]); ++k)
      for (std::size_t j = L.j * s; j < std::min((L.j + 1) * s, cn_[1]); ++j) {
        const std::size_t i0 = L.i * s, i1 = std::min((L.i + 1) * s, cn_[0]);
        if (i1 > i0) std::fill_n(&level_[cell(i0, j, k)], i1 - i0, level);
      }
  }
  // The 8^3 blocks of cells [lo, hi] per axis (clipped to the grid), visited by f(index).
  template <typename F>
  bool any_block(long lo0, long lo1, long lo2, long hi0, long hi1, long hi2, const F& f) const {
    const long lo[3] = {lo0, lo1, lo2}, hi[3] = {hi0, hi1, hi2};
    std::size_t b0[3], b1[3];
    for (int a = 0; a < 3; ++a) {
      const long l = std::max(0L, lo[a]), h = std::min(long(cn_[a]) - 1, hi[a]);
      if (h < l) return false;
      b0[a] = std::size_t(l) / 8, b1[a] = std::size_t(h) / 8;
    }
    for (std::size_t z = b0[2]; z <= b1[2]; ++z)
      for (std::size_t y = b0[1]; y <= b1[1]; ++y)
        for (std::size_t x = b0[0]; x <= b1[0]; ++x)
          if (f(x + db_[0] * (y + db_[1] * z))) return true;
    return false;
  }
  void mark_dirty(const Leaf& L) {
    const long s = long(S(L)), lo[3] = {long(L.i) * s, long(L.j) * s, long(L.k) * s};
    any_block(lo[0], lo[1], lo[2], lo[0] + s - 1, lo[1] + s - 1, lo[2] + s - 1, [&](std::size_t b) { dirty_[b] = 1; return false; });
  }
  bool shell_dirty(const Leaf& L) const {
    const long s = long(S(L)), lo[3] = {long(L.i) * s, long(L.j) * s, long(L.k) * s};
    return any_block(lo[0] - 1, lo[1] - 1, lo[2] - 1, lo[0] + s, lo[1] + s, lo[2] + s, [&](std::size_t b) { return dirty_[b] != 0; });
  }
  void rebuild_levels() {
    level_.assign(cn_[0] * cn_[1] * cn_[2], -1);
    for (const Leaf& L : leaves_) {
      const std::size_t s = S(L);
      for (std::size_t k = L.k * s; k < (L.k + 1) * s; ++k)
        for (std::size_t j = L.j * s; j < (L.j + 1) * s; ++j)
          std::fill_n(&level_[cell(L.i * s, j, k)], s, static_cast<std::int8_t>(L.level));
    }
  }

  // 2:1 balance: an active face-, edge- or vertex-neighbour more than one level finer.
  bool unbalanced(const Leaf& L) const {
    if (L.level < 2) return false;
    const long s = long(S(L)), lo[3] = {long(L.i) * s, long(L.j) * s, long(L.k) * s};
    const long a0 = std::max(0L, lo[0] - 1), a1 = std::min(long(cn_[0]) - 1, lo[0] + s);
    const long b0 = std::max(0L, lo[1] - 1), b1 = std::min(long(cn_[1]) - 1, lo[1] + s);
    const long c0 = std::max(0L, lo[2] - 1), c1 = std::min(long(cn_[2]) - 1, lo[2] + s);
    auto finer = [&](long i, long j, long k) {
      const int lv = level_[cell(std::size_t(i), std::size_t(j), std::size_t(k))];
      return lv >= 0 && lv < L.level - 1;
    };
    for (long k = c0; k <= c1; ++k)
      for (long j = b0; j <= b1; ++j) {
        const bool inner = k >= lo[2] && k < lo[2] + s && j >= lo[1] && j < lo[1] + s;
        if (inner) {  // only the two cells beyond the box along x
          if (lo[0] - 1 >= a0 && finer(lo[0] - 1, j, k)) return true;
          if (lo[0] + s <= a1 && finer(lo[0] + s, j, k)) return true;
        } else {
          for (long i = a0; i <= a1; ++i)
            if (finer(i, j, k)) return true;
        }
      }
    return false;
  }

  // Whether an active leaf finer than L owns a cell around L's edge along axis a through
  // p (the other two coordinates) from t0 to t1: such a leaf sees part of the edge at its own
  // resolution, so both views of the edge must agree.
  bool edge_touches_finer(const Leaf& L, int a, const std::size_t p[3], std::size_t t0, std::size_t t1) const {
    const int u = (a + 1) % 3, w = (a + 2) % 3;
    for (int du = -1; du <= 0; ++du)
      for (int dw = -1; dw <= 0; ++dw) {
        const long cu = long(p[u]) + du, cw = long(p[w]) + dw;
        if (cu < 0 || cw < 0 || cu >= long(cn_[u]) || cw >= long(cn_[w])) continue;
        std::size_t c[3];
        c[u] = std::size_t(cu), c[w] = std::size_t(cw);
        for (std::size_t t = t0; t < t1; ++t) {
          c[a] = t;
          const int lv = level_[cell(c[0], c[1], c[2])];
          if (lv >= 0 && lv < L.level) return true;
        }
      }
    return false;
  }

  // Each of the 12 edges has exactly one finest sign change if its ends differ, else none
  // (on the edges that EdgeRule selects).
  bool edges_consistent(const Leaf& L) const {
    std::size_t lo[3], hi[3];
    box(L, lo, hi);
    for (int a = 0; a < 3; ++a) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      for (int e = 0; e < 4; ++e) {
        std::size_t p[3];
        p[u] = e & 1 ? hi[u] : lo[u];
        p[w] = e & 2 ? hi[w] : lo[w];
        int changes = 0;
        p[a] = lo[a];
        bool prev = in(p[0], p[1], p[2]);
        const bool first = prev;
        for (std::size_t t = lo[a] + 1; t <= hi[a]; ++t) {
          p[a] = t;
          const bool c = in(p[0], p[1], p[2]);
          changes += c != prev;
          prev = c;
        }
        if (changes != (first != prev ? 1 : 0) && (o_.edge_rule == EdgeRule::all || edge_touches_finer(L, a, p, lo[a], hi[a]))) return false;
      }
    }
    return true;
  }

  // The key of the (first) finest crossing on the segment from sample A along axis ax,
  // h steps; false when the ends are of one class.
  bool crossing_key(const std::size_t A[3], int ax, std::size_t h, Key& key) const {
    std::size_t p[3] = {A[0], A[1], A[2]};
    bool prev = in(p[0], p[1], p[2]);
    std::size_t q[3] = {A[0], A[1], A[2]};
    q[ax] += h;
    if (prev == in(q[0], q[1], q[2])) return false;
    for (std::size_t t = 0; t < h; ++t) {
      std::size_t nx[3] = {p[0], p[1], p[2]};
      ++nx[ax];
      const bool c = in(nx[0], nx[1], nx[2]);
      if (c != prev) {
        key = 3 * Key(g_.index(p[0], p[1], p[2])) + Key(ax);
        return true;
      }
      p[ax] = nx[ax];
    }
    return false;
  }

  std::array<double, 3> position(Key key) const {
    const std::size_t lin = std::size_t(key / 3), ax = std::size_t(key % 3);
    std::size_t p[3] = {lin % n_[0], (lin / n_[0]) % n_[1], lin / (n_[0] * n_[1])};
    const float fa = g_.at(p[0], p[1], p[2]);
    std::size_t q[3] = {p[0], p[1], p[2]};
    ++q[ax];
    const float fb = g_.at(q[0], q[1], q[2]);
    const double t = (static_cast<double>(iso_) - fa) / (static_cast<double>(fb) - fa);
    double x[3] = {double(p[0]), double(p[1]), double(p[2])};
    x[ax] += t;
    return g_.world(x[0], x[1], x[2]);
  }

  // Face f of leaf L is split iff an active leaf across it is finer.
  bool face_split(const Leaf& L, int f) const {
    if (L.level == 0) return false;
    const int a = f / 2, u = (a + 1) % 3, w = (a + 2) % 3;
    const std::size_t s = S(L), idx[3] = {L.i, L.j, L.k};
    long c = long(idx[a] * s) + (f % 2 ? long(s) : -1L);
    if (c < 0 || c >= long(cn_[a])) return false;
    std::size_t p[3];
    p[a] = std::size_t(c);
    for (std::size_t y = idx[w] * s; y < (idx[w] + 1) * s; ++y)
      for (std::size_t x = idx[u] * s; x < (idx[u] + 1) * s; ++x) {
        p[u] = x, p[w] = y;
        const int lv = level_[cell(p[0], p[1], p[2])];
        if (lv >= 0 && lv < L.level) return true;
      }
    return false;
  }

  // Loops of one leaf from the segments of its (sub-)faces (2.5 step 3).
  LeafLoops leaf_loops(const Leaf& L) const {
    std::vector<std::pair<Key, Key>> next;
    std::vector<std::pair<Key, std::uint8_t>> mask;
    const std::size_t s = S(L), idx[3] = {L.i, L.j, L.k};
    for (int f = 0; f < 6; ++f) {
      const int a = f / 2, u = (a + 1) % 3, w = (a + 2) % 3;
      const bool split = face_split(L, f);
      const std::size_t h = split ? s / 2 : s, parts = split ? 2 : 1;
      for (std::size_t pw = 0; pw < parts; ++pw)
        for (std::size_t pu = 0; pu < parts; ++pu) {
          // corners in square order (u, w): (0,0), (1,0), (1,1), (0,1)
          std::size_t q[4][3];
          const std::size_t su[4] = {0, 1, 1, 0}, sw[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            q[c][a] = idx[a] * s + (f % 2 ? s : 0);
            q[c][u] = idx[u] * s + pu * h + su[c] * h;
            q[c][w] = idx[w] * s + pw * h + sw[c] * h;
          }
          bool inside[4];
          double gval[4];
          for (int c = 0; c < 4; ++c) gval[c] = double(g_.at(q[c][0], q[c][1], q[c][2])) - iso_, inside[c] = gval[c] >= 0;
          // square edge k joins corners k and k+1; its lower end and axis
          Key key[4];
          bool has[4];
          for (int k = 0; k < 4; ++k) {
            const int c0 = k, c1 = (k + 1) % 4;
            const int lower = (k == 2) ? 3 : (k == 3 ? 0 : c0);
            const int ax = (k % 2 == 0) ? u : w;
            has[k] = inside[c0] != inside[c1] && crossing_key(q[lower], ax, h, key[k]);
          }
          std::vector<std::array<int, 2>> segs;
          const int crossed = has[0] + has[1] + has[2] + has[3];
          if (crossed == 2) {
            int e0 = -1, e1 = -1;
            for (int k = 0; k < 4; ++k)
              if (has[k]) (e0 < 0 ? e0 : e1) = k;
            segs.push_back({e0, e1});
          } else if (crossed == 4) {
            const bool connect = o_.face_rule == FaceRule::decider && inside_connected(gval[0], gval[1], gval[2], gval[3]);
            for (int k = 0; k < 4; ++k)
              if (inside[k] != connect) segs.push_back({(k + 3) % 4, k});
          }
          for (auto sg : segs) {
            int ep = sg[0], eq = sg[1];
            // orient: n_f x (q - p) points away from the inside corner of p's edge
            auto mid = [&](int k) {
              std::array<double, 3> m;
              for (int c = 0; c < 3; ++c) m[c] = 0.5 * (double(q[k][c]) + double(q[(k + 1) % 4][c]));
              return m;
            };
            const auto P = mid(ep), Q = mid(eq);
            const int kin = inside[ep] ? ep : (ep + 1) % 4;
            double nf[3] = {0, 0, 0};
            nf[a] = f % 2 ? 1.0 : -1.0;
            const double d[3] = {Q[0] - P[0], Q[1] - P[1], Q[2] - P[2]};
            const double x[3] = {nf[1] * d[2] - nf[2] * d[1], nf[2] * d[0] - nf[0] * d[2], nf[0] * d[1] - nf[1] * d[0]};
            double side = 0;
            for (int c = 0; c < 3; ++c) side += x[c] * (double(q[kin][c]) - P[c]);
            if (side > 0) std::swap(ep, eq);
            next.emplace_back(key[ep], key[eq]);
            mask.emplace_back(key[ep], static_cast<std::uint8_t>(1 << f));
            mask.emplace_back(key[eq], static_cast<std::uint8_t>(1 << f));
          }
        }
    }
    std::sort(next.begin(), next.end());
    std::sort(mask.begin(), mask.end());
    LeafLoops out;
    std::vector<char> used(next.size(), 0);
    auto find_next = [&](Key k) -> std::ptrdiff_t {
      const auto it = std::lower_bound(next.begin(), next.end(), std::make_pair(k, Key{0}));
      return it != next.end() && it->first == k ? it - next.begin() : -1;
    };
    auto mask_of = [&](Key k) {
      std::uint8_t m = 0;
      for (auto it = std::lower_bound(mask.begin(), mask.end(), std::make_pair(k, std::uint8_t{0})); it != mask.end() && it->first == k; ++it)
        m |= it->second;
      return m;
    };
    for (std::size_t s0 = 0; s0 < next.size(); ++s0) {
      if (used[s0]) continue;
      std::uint32_t len = 0;
      for (std::ptrdiff_t e = std::ptrdiff_t(s0); e >= 0 && !used[std::size_t(e)];) {
        used[std::size_t(e)] = 1;
        out.keys.push_back(next[std::size_t(e)].first);
        out.masks.push_back(mask_of(next[std::size_t(e)].first));
        ++len;
        e = find_next(next[std::size_t(e)].second);
      }
      out.lengths.push_back(len);
    }
    return out;
  }

  void triangulate(AdaptiveResult& r) const {
    std::vector<LeafLoops> loops(leaves_.size());
    parallel_for(leaves_.size(), o_.threads, [&](std::size_t t) { loops[t] = leaf_loops(leaves_[t]); });
    std::vector<Key> keys;
    for (const auto& L : loops) keys.insert(keys.end(), L.keys.begin(), L.keys.end());
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    Surface& s = r.surface;
    s.xyz.resize(3 * keys.size());
    std::vector<std::array<double, 3>> pos(keys.size());
    parallel_for(keys.size(), o_.threads, [&](std::size_t v) {
      pos[v] = position(keys[v]);
      for (int c = 0; c < 3; ++c) s.xyz[3 * v + c] = static_cast<float>(pos[v][c]);
    });
    std::vector<std::vector<std::array<std::uint32_t, 3>>> tris(leaves_.size());
    std::vector<std::vector<std::array<double, 3>>> cents(leaves_.size());
    parallel_for(leaves_.size(), o_.threads, [&](std::size_t t) {
      const LeafLoops& L = loops[t];
      std::size_t at = 0;
      std::vector<std::uint32_t> ids;
      std::vector<std::array<double, 3>> pts;
      std::vector<std::uint8_t> masks;
      for (std::uint32_t len : L.lengths) {
        ids.clear(), pts.clear(), masks.clear();
        for (std::uint32_t m = 0; m < len; ++m) {
          const auto id = static_cast<std::uint32_t>(std::lower_bound(keys.begin(), keys.end(), L.keys[at + m]) - keys.begin());
          ids.push_back(id);
          pts.push_back(pos[id]);
          masks.push_back(L.masks[at + m] & 0x15);  // lower faces only (see triangulate_loop.hpp)
        }
        at += len;
        if (len < 3) continue;  // cannot happen for consistent leaves
        if (!triangulate_loop(ids.data(), pts.data(), masks.data(), int(len), o_.triangulation, tris[t])) {
          std::array<double, 3> c{0, 0, 0};
          for (const auto& p : pts)
            for (int a = 0; a < 3; ++a) c[a] += p[a] / len;
          const std::uint32_t cid = 0x80000000u | static_cast<std::uint32_t>(cents[t].size());
          cents[t].push_back(c);
          for (std::uint32_t m = 0; m < len; ++m) tris[t].push_back({cid, ids[m], ids[(m + 1) % len]});
        }
      }
    });
    for (std::size_t t = 0; t < leaves_.size(); ++t) {
      const auto first = static_cast<std::uint32_t>(s.vertices());
      for (auto tri : tris[t]) {
        for (auto& v : tri)
          if (v & 0x80000000u) v = first + (v & 0x7fffffffu);
        s.triangles.push_back(tri);
      }
      for (const auto& c : cents[t])
        for (int a = 0; a < 3; ++a) s.xyz.push_back(static_cast<float>(c[a]));
      r.centroid_vertices += cents[t].size();
    }
    if (g_.determinant() < 0)
      for (auto& t : s.triangles) std::swap(t[1], t[2]);
  }

  const ScalarGrid& g_;
  float iso_;
  const AdaptiveOptions& o_;
  const MinMaxPyramid& pyr_;
  std::size_t n_[3], cn_[3];
  int root_ = 0, max_level_ = 0;
  double r0_ = 1;
  double max_error_bound_ = 0;
  std::vector<Leaf> leaves_;
  std::vector<std::int8_t> level_;
  std::vector<char> dirty_;          // 8^3 blocks of cells whose levels changed in the last closure pass
  std::size_t db_[3] = {0, 0, 0};
};

}  // namespace

AdaptiveResult extract_adaptive(const ScalarGrid& grid, float iso, const AdaptiveOptions& options, const MinMaxPyramid& pyramid) {
  if (grid.dims[0] < 2 || grid.dims[1] < 2 || grid.dims[2] < 2) return {};
  return Adaptive(grid, iso, options, pyramid).run();
}

}  // namespace fest::isosurface

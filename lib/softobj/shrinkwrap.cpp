#include "softobj/shrinkwrap.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <vector>

#include "core/error.hpp"

namespace fest::softobj {

namespace {

using VH = TriMesh::VertexHandle;
using Vec = Eigen::Vector3d;

Vec P(const TriMesh& m, VH v) {
  const auto& p = m.point(v);
  return {p[0], p[1], p[2]};
}
void set_P(TriMesh& m, VH v, const Vec& p) { m.set_point(v, TriMesh::Point(p.x(), p.y(), p.z())); }
Vec N(const TriMesh& m, VH v) {
  const auto& n = m.normal(v);
  return {n[0], n[1], n[2]};
}
double angle(const Vec& a, const Vec& b) { return std::acos(std::clamp(a.dot(b), -1.0, 1.0)); }

// Icosahedron subdivided `level` times (1 -> 4), unit radius, faces outward.
void icosphere(int level, std::vector<Vec>& V, std::vector<std::array<int, 3>>& F) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  V = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  F = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
       {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
       {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& v : V) v.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      V.push_back((V[a] + V[b]).normalized());
      return mid[key] = static_cast<int>(V.size()) - 1;
    };
    std::vector<std::array<int, 3>> G;
    for (const auto& f : F) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      G.push_back({f[0], a, c});
      G.push_back({f[1], b, a});
      G.push_back({f[2], c, b});
      G.push_back({a, b, c});
    }
    F.swap(G);
  }
}

class Wrapper {
 public:
  Wrapper(const Field& f, const ShrinkwrapOptions& o, ShrinkwrapStats& s) : field_(f), o_(o), st_(s) {
    alpha_ = o.alpha_deg * M_PI / 180;
  }

  TriMesh run() {
    const CompiledSkeleton& c = field_.skeleton();
    if (field_.kernel().kind != Kernel::coulomb)
      throw usage_error("shrink-wrap needs the Coulomb kernel's far field; a compact kernel needs marching cubes");
    const double Q = c.total_charge;
    if (!(Q > 0))
      throw bad_input("the skeleton's total charge is {} (Euler characteristic {}): shrink-wrap needs a far-field "
                      "sphere (Q > 0); polygonize it with marching cubes",
                      Q, c.euler_characteristic);
    const double vstar = o_.iso;
    lmax_ = o_.lmax > 0 ? o_.lmax : Q / vstar;
    st_.lmax = lmax_;
    const double rb = std::max({c.bound_radius, Q / vstar, 1e-12});
    const double v0 = std::min(Q / (4 * rb), vstar);
    st_.v0 = v0;
    start_mesh(c.centre, v0);
    const double lmax_final = lmax_;
    for (int k = 1; k <= o_.steps; ++k) {
      const double vk = v0 * std::pow(vstar / v0, static_cast<double>(k) / o_.steps);
      // The length bound matters on the final surface only: on the larger intermediate
      // surfaces (radius ~ Q/V_k far out) it grows with them, so the triangle count stays
      // about constant while shrinking (our addition; docs/softobj.md §3).
      lmax_ = lmax_final * std::max(1.0, vstar / vk);
      dev_tol_ = o_.max_deviation * std::max(1.0, vstar / vk);  // sizes scale alike
      pass(vk, o_.newton_tol);
    }
    lmax_ = lmax_final;
    dev_tol_ = o_.max_deviation;
    pass(vstar, 1e-12);  // final pass at V* (docs/softobj.md §3, step 4)
    finish(vstar);
    return std::move(m_);
  }

 private:
  const Field& field_;
  const ShrinkwrapOptions& o_;
  ShrinkwrapStats& st_;
  TriMesh m_;
  double alpha_ = 0, lmax_ = 0;
  double dev_tol_ = 0;  // current deviation tolerance (0 = off)
  double value_ = 0;    // the iso value of the current pass

  // Distance of p from the current iso-surface f = value_, by Newton projection (the
  // measure of docs/softobj.md §6); infinite when the projection fails.
  double deviation(const Vec& p) const {
    Vec r = p;
    if (!project_to_iso(field_, r, value_, 1e-9, 0.5 * lmax_)) return HUGE_VAL;
    return (r - p).norm();
  }
  double chord_deviation(VH a, VH b) const { return deviation(0.5 * (P(m_, a) + P(m_, b))); }
  double centroid_deviation(const Vec& a, const Vec& b, const Vec& c) const { return deviation((a + b + c) / 3); }

  void start_mesh(const Vec& centre, double v0) {
    std::vector<Vec> V;
    std::vector<std::array<int, 3>> F;
    icosphere(std::clamp(o_.start_level, 0, 6), V, F);
    m_.request_vertex_normals();
    m_.request_vertex_status();
    m_.request_edge_status();
    m_.request_halfedge_status();
    m_.request_face_status();
    std::vector<VH> vh;
    const double r0 = 4 * std::max(field_.skeleton().bound_radius, 1e-9);
    for (const Vec& d : V) {
      // Along the ray from the centre, the outermost crossing of f = V_0 (bisection).
      double hi = r0;
      while (field_.value(centre + hi * d) > v0) hi *= 2;
      double lo = hi;
      while (field_.value(centre + lo * d) < v0 && lo > 1e-12 * r0) lo *= 0.5;
      for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (field_.value(centre + mid * d) > v0 ? lo : hi) = mid;
      }
      vh.push_back(m_.add_vertex(TriMesh::Point(0, 0, 0)));
      set_P(m_, vh.back(), centre + 0.5 * (lo + hi) * d);
    }
    for (const auto& f : F) m_.add_face(vh[f[0]], vh[f[1]], vh[f[2]]);
  }

  void update_normal(VH v) {
    const Vec g = field_.eval(P(m_, v)).grad;
    const Vec n = g.norm() > 0 ? Vec(-g.normalized()) : Vec(0, 0, 1);
    m_.set_normal(v, TriMesh::Normal(n.x(), n.y(), n.z()));
  }

  bool project(VH v, double value, double tol) {
    Vec p = P(m_, v);
    const bool ok = project_to_iso(field_, p, value, tol, 0.5 * lmax_);
    set_P(m_, v, p);
    update_normal(v);
    return ok;
  }

  void pass(double value, double tol) {
    value_ = value;
    for (auto v : m_.vertices()) project(v, value, tol);
    if (o_.relax > 0) relax(value, tol);
    refine(value, tol);
    if (dev_tol_ > 0) refine_faces(value, tol);
    if (o_.coarsen) coarsen();
    flip_to_delaunay();
    // The flips remove the slivers that deviation refinement had to skip; what they leave
    // beyond the tolerance is refined again (a few rounds: each can create slivers anew).
    for (int round = 0; round < 3 && dev_tol_ > 0 && refine_faces(value, tol); ++round) flip_to_delaunay();
  }

  // Edge flips towards the Delaunay triangulation (our addition, docs/softobj.md §3, step 3 (e)):
  // an edge whose opposite angles sum to more than pi is flipped when the new chord is
  // acceptable and neither new triangle folds against the field normals. Thin triangles
  // from splitting and collapsing are what fold when the surface shrinks further.
  void flip_to_delaunay() {
    for (int sweep = 0; sweep < 4; ++sweep) {
      std::size_t flips = 0;
      for (auto e : m_.edges()) {
        if (!m_.is_flip_ok(e)) continue;
        const auto h0 = m_.halfedge_handle(e, 0), h1 = m_.halfedge_handle(e, 1);
        const VH a = m_.to_vertex_handle(h0), b = m_.to_vertex_handle(h1);
        const VH c = m_.to_vertex_handle(m_.next_halfedge_handle(h0));
        const VH d = m_.to_vertex_handle(m_.next_halfedge_handle(h1));
        const Vec pa = P(m_, a), pb = P(m_, b), pc = P(m_, c), pd = P(m_, d);
        auto opp = [](const Vec& apex, const Vec& u, const Vec& w) {
          const Vec x = u - apex, y = w - apex;
          return std::atan2(x.cross(y).norm(), x.dot(y));
        };
        if (opp(pc, pa, pb) + opp(pd, pa, pb) <= M_PI + 1e-9) continue;
        if ((pc - pd).norm() > lmax_ || angle(N(m_, c), N(m_, d)) > alpha_) continue;
        if (dev_tol_ > 0) {  // the new chord and triangles within the tolerance, or no worse than before
          const double t = std::max(0.8 * dev_tol_, std::max(centroid_deviation(pb, pa, pc), centroid_deviation(pa, pb, pd)));
          if (deviation(0.5 * (pc + pd)) > t || centroid_deviation(pa, pc, pd) > t ||
              centroid_deviation(pc, pb, pd) > t)
            continue;
        }
        // h0 runs b -> a in face (b, a, c), h1 runs a -> b in face (a, b, d): the quad is
        // a c b d, and the flipped triangles are (a, c, d) and (c, b, d).
        auto agrees = [](const Vec& p0, const Vec& p1, const Vec& p2, const Vec& n) {
          return (p1 - p0).cross(p2 - p0).normalized().dot(n) > 0.5;
        };
        if (!agrees(pa, pc, pd, (N(m_, a) + N(m_, c) + N(m_, d)).normalized()) ||
            !agrees(pc, pb, pd, (N(m_, c) + N(m_, b) + N(m_, d)).normalized()))
          continue;
        m_.flip(e);
        ++flips;
      }
      if (!flips) break;
    }
  }

  // Tangential umbrella smoothing (docs/softobj.md §3, step 3 (b)), then re-projection.
  void relax(double value, double tol) {
    std::vector<Vec> moved(m_.n_vertices());
    for (auto v : m_.vertices()) {
      Vec mean = Vec::Zero();
      int n = 0;
      for (auto w : m_.vv_range(v)) mean += P(m_, w), ++n;
      const Vec p = P(m_, v), nv = N(m_, v);
      Vec u = n ? Vec(mean / n - p) : Vec::Zero();
      u -= u.dot(nv) * nv;
      moved[v.idx()] = p + o_.relax * u;
    }
    for (auto v : m_.vertices()) {
      set_P(m_, v, moved[v.idx()]);
      project(v, value, tol);
    }
  }

  bool unacceptable(TriMesh::EdgeHandle e, double* len) const {
    const auto h = m_.halfedge_handle(e, 0);
    const VH a = m_.from_vertex_handle(h), b = m_.to_vertex_handle(h);
    *len = (P(m_, a) - P(m_, b)).norm();
    if (*len <= 1e-3 * lmax_) return false;  // no endless splitting across a fold: the fold check repairs it
    if (*len > lmax_ || angle(N(m_, a), N(m_, b)) > alpha_) return true;
    if (!(dev_tol_ > 0)) return false;
    // A circular arc's sagitta is at most half its chord: a midpoint farther off is not on
    // a bend of this sheet but across a fold or gap of the membrane, where splitting would
    // not converge; the chord rule and the fold check deal with those.
    const double d = chord_deviation(a, b);
    if (!(d > dev_tol_ && d <= 0.5 * *len)) return false;
    // A sliver whose apex lies near the chord's arc: the split point would land on the
    // apex (a zero-length chord, and the same again on the other side, endlessly). The
    // Delaunay flip that follows refinement removes such a chord instead.
    for (int side = 0; side < 2; ++side) {
      const auto hs = m_.halfedge_handle(e, side);
      if (m_.is_boundary(hs)) continue;
      const Vec c = P(m_, m_.to_vertex_handle(m_.next_halfedge_handle(hs)));
      const Vec x = P(m_, m_.from_vertex_handle(hs)) - c, y = P(m_, m_.to_vertex_handle(hs)) - c;
      if (std::atan2(x.cross(y).norm(), x.dot(y)) > 150 * M_PI / 180) return false;
    }
    return true;
  }

  // Split edge e at its midpoint (both triangles 1 -> 2: conforming, no T-junctions) and
  // Newton-project the new vertex onto the surface.
  VH split_edge(TriMesh::EdgeHandle e, double value, double tol) {
    if (m_.n_vertices() >= o_.max_vertices)
      throw runtime_failure("more than {} vertices (the vertex limit; a surface that is not genus 0 also "
                            "does this)",
                            o_.max_vertices);
    const auto h = m_.halfedge_handle(e, 0);
    const Vec mid = 0.5 * (P(m_, m_.from_vertex_handle(h)) + P(m_, m_.to_vertex_handle(h)));
    const VH nv = m_.add_vertex(TriMesh::Point(mid.x(), mid.y(), mid.z()));
    m_.split(e, nv);
    ++st_.splits;
    project(nv, value, tol);
    return nv;
  }

  // Deviation-driven triangle refinement (docs/softobj.md §3, step 3 (c')): a triangle whose
  // centroid lies farther than the tolerance from the surface has its longest edge split
  // (Rivara's longest-edge bisection; the neighbour across that edge is split too, so the
  // mesh stays conforming), then the chords at the new vertices are checked as in refine.
  // Returns whether anything was split.
  bool refine_faces(double value, double tol) {
    const std::size_t before = st_.splits;
    refine(value, tol);
    for (int round = 0; round < 12; ++round) {
      std::vector<int> longest;
      for (auto f : m_.faces()) {
        std::array<Vec, 3> q;
        int k = 0;
        for (auto v : m_.fv_range(f)) q[k++] = P(m_, v);
        const double d = centroid_deviation(q[0], q[1], q[2]);
        if (d <= dev_tol_) continue;
        double best = -1;
        TriMesh::HalfedgeHandle best_h;
        for (auto h : m_.fh_range(f)) {
          const double l = (P(m_, m_.from_vertex_handle(h)) - P(m_, m_.to_vertex_handle(h))).norm();
          if (l > best) best = l, best_h = h;
        }
        // As in unacceptable(): not across a fold, not the base of a sliver (apex > 150 deg).
        const Vec apex = P(m_, m_.to_vertex_handle(m_.next_halfedge_handle(best_h)));
        const Vec x = P(m_, m_.from_vertex_handle(best_h)) - apex, y = P(m_, m_.to_vertex_handle(best_h)) - apex;
        if (std::atan2(x.cross(y).norm(), x.dot(y)) > 150 * M_PI / 180) continue;
        if (best > 1e-3 * lmax_ && d <= 0.5 * best) longest.push_back(m_.edge_handle(best_h).idx());
      }
      if (longest.empty()) break;
      std::sort(longest.begin(), longest.end());
      longest.erase(std::unique(longest.begin(), longest.end()), longest.end());
      for (int ei : longest) split_edge(m_.edge_handle(ei), value, tol);
      refine(value, tol);
    }
    return st_.splits != before;
  }

  // Split unacceptable chords, longest first (docs/softobj.md §3, step 3 (c)).
  void refine(double value, double tol) {
    std::priority_queue<std::pair<double, int>> q;
    for (auto e : m_.edges()) {
      double len;
      if (unacceptable(e, &len)) q.push({len, e.idx()});
    }
    while (!q.empty()) {
      const auto e = m_.edge_handle(q.top().second);
      q.pop();
      double len;
      if (!unacceptable(e, &len)) continue;
      const VH nv = split_edge(e, value, tol);
      for (auto ve : m_.ve_range(nv)) {  // only the edges at the new vertex are new
        double l;
        if (unacceptable(ve, &l)) q.push({l, ve.idx()});
      }
    }
  }

  // Collapse short, flat chords into one end (that end stays on the surface) when every
  // chord created stays acceptable with margin and no triangle folds (docs/softobj.md §3, step 3 (d)).
  void coarsen() {
    std::vector<std::pair<double, int>> cand;
    for (auto e : m_.edges()) {
      const auto h = m_.halfedge_handle(e, 0);
      const VH a = m_.from_vertex_handle(h), b = m_.to_vertex_handle(h);
      const double len = (P(m_, a) - P(m_, b)).norm();
      if (len < 0.5 * lmax_ && angle(N(m_, a), N(m_, b)) < 0.5 * alpha_) cand.push_back({len, e.idx()});
    }
    std::sort(cand.begin(), cand.end());
    std::vector<char> touched(m_.n_vertices(), 0);
    bool any = false;
    for (const auto& [len, ei] : cand) {
      const auto e = m_.edge_handle(ei);
      if (m_.status(e).deleted()) continue;
      for (int side = 0; side < 2; ++side) {
        const auto h = m_.halfedge_handle(e, side);
        const VH v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
        if (touched[v0.idx()] || touched[v1.idx()]) break;
        if (!m_.is_collapse_ok(h) || !collapse_keeps_quality(v0, v1)) continue;
        for (auto w : m_.vv_range(v0)) touched[w.idx()] = 1;
        touched[v0.idx()] = touched[v1.idx()] = 1;
        m_.collapse(h);
        ++st_.collapses;
        any = true;
        break;
      }
    }
    if (any) m_.garbage_collection();
  }

  bool collapse_keeps_quality(VH v0, VH v1) const {
    const Vec p1 = P(m_, v1), n1 = N(m_, v1);
    if (m_.valence(v1) + m_.valence(v0) > 14) return false;
    for (auto w : m_.vv_range(v0)) {
      if (w == v1) continue;
      if ((P(m_, w) - p1).norm() > 0.8 * lmax_ || angle(N(m_, w), n1) > 0.8 * alpha_) return false;
      if (dev_tol_ > 0 && deviation(0.5 * (P(m_, w) + p1)) > 0.8 * dev_tol_) return false;
    }
    for (auto f : m_.vf_range(v0)) {
      std::array<Vec, 3> q;
      Vec nsum = Vec::Zero();
      int k = 0;
      bool has_v1 = false;
      for (auto v : m_.fv_range(f)) {
        if (v == v1) has_v1 = true;
        q[k] = v == v0 ? p1 : P(m_, v);
        nsum += v == v0 ? n1 : N(m_, v);
        ++k;
      }
      if (has_v1) continue;  // removed by the collapse
      const Vec g = (q[1] - q[0]).cross(q[2] - q[0]);
      if (g.norm() <= 0 || g.normalized().dot(nsum.normalized()) < 0.5) return false;
      if (dev_tol_ > 0 && centroid_deviation(q[0], q[1], q[2]) > 0.8 * dev_tol_) return false;
      for (int i = 0; i < 3; ++i) {  // keep the smallest angle above 10 degrees
        const Vec a = q[(i + 1) % 3] - q[i], b = q[(i + 2) % 3] - q[i];
        if (std::atan2(a.cross(b).norm(), a.dot(b)) < 10 * M_PI / 180) return false;
      }
    }
    return true;
  }

  std::vector<TriMesh::FaceHandle> folded_faces() const {
    std::vector<TriMesh::FaceHandle> out;
    for (auto f : m_.faces()) {
      std::array<Vec, 3> q;
      int k = 0;
      for (auto v : m_.fv_range(f)) q[k++] = P(m_, v);
      const Vec g = (q[1] - q[0]).cross(q[2] - q[0]);
      const Vec grad = field_.eval((q[0] + q[1] + q[2]) / 3).grad;
      if (g.dot(-grad) <= 0) out.push_back(f);
    }
    return out;
  }

  // Fold check and repair (docs/softobj.md §3, step 5): the vertices of folded triangles and
  // their neighbours move to their tangential umbrella centre and back onto the surface.
  void finish(double vstar) {
    auto folded = folded_faces();
    for (int attempt = 0; attempt < 3 && !folded.empty(); ++attempt) {
      std::vector<VH> verts;
      for (auto f : folded)
        for (auto v : m_.fv_range(f)) {
          verts.push_back(v);
          for (auto w : m_.vv_range(v)) verts.push_back(w);
        }
      for (int round = 0; round < 4; ++round)
        for (VH v : verts) {
          Vec mean = Vec::Zero();
          int n = 0;
          for (auto w : m_.vv_range(v)) mean += P(m_, w), ++n;
          const Vec p = P(m_, v), nv = N(m_, v);
          Vec u = mean / n - p;
          u -= u.dot(nv) * nv;
          set_P(m_, v, p + u);
          project(v, vstar, 1e-12);
        }
      refine(vstar, 1e-12);
      folded = folded_faces();
    }
    double worst = 0;
    for (auto v : m_.vertices()) worst = std::max(worst, std::abs(field_.value(P(m_, v)) - vstar) / vstar);
    st_.max_abs_f_err_rel = worst;
    if (worst > o_.newton_tol || !folded.empty())
      throw runtime_failure("surface is not genus 0 ({} folded triangles, largest |f - V*|/V* {:.3g})",
                            folded.size(), worst);
  }
};

}  // namespace

bool project_to_iso(const Field& field, Eigen::Vector3d& r, double value, double tol, double max_step) {
  for (int it = 0; it < 100; ++it) {
    const FieldSample s = field.eval(r);
    const double err = value - s.f;
    if (std::abs(err) <= tol * value) return true;
    const double g2 = s.grad.squaredNorm();
    if (!(g2 > 1e-300)) return false;
    Eigen::Vector3d step = (err / g2) * s.grad;  // linearisation of f (seed App. D §4.3)
    const double len = step.norm();
    if (max_step > 0 && len > max_step) step *= max_step / len;  // damped
    r += step;
  }
  return false;
}

TriMesh shrinkwrap(const Field& field, const ShrinkwrapOptions& options, ShrinkwrapStats* stats) {
  if (!(options.iso > 0)) throw usage_error("iso value {} is not positive", options.iso);
  ShrinkwrapStats local;
  ShrinkwrapStats& st = stats ? *stats : local;
  try {
    Wrapper w(field, options, st);
    return w.run();
  } catch (const Error& e) {
    if (e.status() != Status::failure) throw;
  }
  // One retry with twice the iso steps and a finer start mesh: a surface with deep
  // concavities (a tongue tip curled back towards its body, a strip folding over itself)
  // can trap vertices when it shrinks too fast from too coarse a membrane.
  ShrinkwrapOptions slower = options;
  slower.steps = 2 * options.steps;
  slower.start_level = std::min(options.start_level + 1, 6);
  st = ShrinkwrapStats{};
  Wrapper w(field, slower, st);
  return w.run();
}

}  // namespace fest::softobj

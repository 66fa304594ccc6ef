#include "decimate/simplify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "core/error.hpp"
#include "decimate/quadric.hpp"

namespace fest::decimate {

namespace {

using VH = TriMesh::VertexHandle;
using HH = TriMesh::HalfedgeHandle;
using EH = TriMesh::EdgeHandle;
using FH = TriMesh::FaceHandle;

// The layout of a vertex in R^n (docs/decimate.md 2.1): position, then each attribute the
// mesh carries, scaled by the attribute weight so that a unit attribute difference counts
// as `weight` bounding-box diagonals.
struct Layout {
  int n = 3;
  int normal = -1, color = -1, texcoord = -1;
  double scale = 1;  // attribute units -> length units
};

// A view of a packed quadric with the calls of Quadric.
struct PackedQuadric {
  const double* q;
  int n;
  double evaluate(const double* v) const { return Quadric::evaluate_packed(q, n, v); }
  bool minimise(double* v) const { return Quadric::minimise_packed(q, n, v); }
};

struct Candidate {
  double cost;
  std::uint32_t edge;
  std::uint32_t version;
  bool operator<(const Candidate& o) const {  // std::priority_queue is a max-heap
    return cost != o.cost ? cost > o.cost : edge > o.edge;
  }
};

class Engine {
 public:
  Engine(TriMesh& m, const SimplifyOptions& opt, SimplifyStats& st) : mesh_(m), opt_(opt), st_(st) {}

  void run() {
    setup_layout();
    build_quadrics();
    const std::size_t ne = mesh_.n_edges();
    version_.assign(ne, 0);
    for (std::size_t e = 0; e < ne; ++e) push(EH(static_cast<int>(e)));
    std::size_t faces = mesh_.n_faces();
    const std::size_t first_faces = faces;
    const std::size_t to_remove = first_faces - std::min(first_faces, opt_.target_faces);
    const auto report = [&] {
      if (opt_.progress) opt_.progress(std::min(first_faces - faces, to_remove), to_remove);
    };
    while (!heap_.empty()) {
      if (opt_.target_faces > 0 && faces <= opt_.target_faces) break;
      const Candidate c = heap_.top();
      heap_.pop();
      const EH e(static_cast<int>(c.edge));
      if (mesh_.status(e).deleted() || c.version != version_[c.edge]) continue;
      if (opt_.max_error >= 0 && error_estimate_of(c.cost, e) > opt_.max_error) break;
      Plan plan;
      if (!plan_collapse(e, plan)) continue;  // re-queued when its neighbourhood changes
      const std::size_t removed = mesh_.is_boundary(e) ? 1 : 2;
      collapse(plan);
      faces -= removed;
      ++st_.collapses;
      st_.max_error_estimate = std::max(st_.max_error_estimate, plan.estimate);
      if (st_.collapses % 4096 == 0) report();
    }
    report();
    st_.reached_target = opt_.target_faces > 0 && faces <= opt_.target_faces;
  }

  const Layout& layout() const { return layout_; }

 private:
  struct Plan {
    HH h;                       // from-vertex disappears, to-vertex survives at `v`
    double v[max_dimension];
    double estimate = 0;
  };

  void setup_layout() {
    int n = 3;
    if (opt_.use_normals && mesh_.has_vertex_normals()) { layout_.normal = n; n += 3; }
    if (opt_.use_colors && mesh_.has_vertex_colors()) { layout_.color = n; n += 3; }
    if (opt_.use_texcoords && mesh_.has_vertex_texcoords2D()) { layout_.texcoord = n; n += 2; }
    layout_.n = n;
    st_.dimension = n;
    OpenMesh::Vec3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const VH v : mesh_.vertices()) {
      lo.minimize(mesh_.point(v));
      hi.maximize(mesh_.point(v));
    }
    const double diag = mesh_.n_vertices() > 0 ? (hi - lo).norm() : 1.0;
    layout_.scale = opt_.attribute_weight * (diag > 0 ? diag : 1.0);
  }

  void vertex_vector(VH v, double* x) const {
    const auto& p = mesh_.point(v);
    x[0] = p[0]; x[1] = p[1]; x[2] = p[2];
    if (layout_.normal >= 0) {
      const auto& nn = mesh_.normal(v);
      for (int i = 0; i < 3; ++i) x[layout_.normal + i] = nn[i] * layout_.scale;
    }
    if (layout_.color >= 0) {
      const auto& c = mesh_.color(v);
      for (int i = 0; i < 3; ++i) x[layout_.color + i] = c[i] / 255.0 * layout_.scale;
    }
    if (layout_.texcoord >= 0) {
      const auto& t = mesh_.texcoord2D(v);
      for (int i = 0; i < 2; ++i) x[layout_.texcoord + i] = t[i] * layout_.scale;
    }
  }

  void store_vector(VH v, const double* x) {
    mesh_.set_point(v, OpenMesh::Vec3d(x[0], x[1], x[2]));
    if (layout_.normal >= 0) {
      OpenMesh::Vec3d nn(x[layout_.normal], x[layout_.normal + 1], x[layout_.normal + 2]);
      const double l = nn.norm();
      if (l > 0) mesh_.set_normal(v, nn / l);
    }
    if (layout_.color >= 0) {
      OpenMesh::Vec3uc c;
      for (int i = 0; i < 3; ++i)
        c[i] = static_cast<unsigned char>(std::clamp(std::lround(x[layout_.color + i] / layout_.scale * 255.0), 0L, 255L));
      mesh_.set_color(v, c);
    }
    if (layout_.texcoord >= 0)
      mesh_.set_texcoord2D(v, OpenMesh::Vec2f(static_cast<float>(x[layout_.texcoord] / layout_.scale),
                                              static_cast<float>(x[layout_.texcoord + 1] / layout_.scale)));
  }

  bool is_feature(EH e) const {
    if (mesh_.is_boundary(e) || opt_.feature_angle_deg >= 180) return false;
    const FH f0 = mesh_.face_handle(mesh_.halfedge_handle(e, 0)), f1 = mesh_.face_handle(mesh_.halfedge_handle(e, 1));
    const auto n0 = mesh_.calc_face_normal(f0), n1 = mesh_.calc_face_normal(f1);
    return OpenMesh::dot(n0, n1) < std::cos(opt_.feature_angle_deg * M_PI / 180.0);
  }

  // GH97 eq. 1-2 (area-weighted, section 7) and GH98's generalisation; boundary and
  // feature edges add a plane through the edge perpendicular to its face (GH97 6).
  void build_quadrics() {
    const int n = layout_.n;
    stride_ = Quadric::packed_size(n);
    quadric_.assign(mesh_.n_vertices() * stride_, 0.0);
    locked_.assign(mesh_.n_vertices(), 0);
    double x[3][max_dimension];
    for (const FH f : mesh_.faces()) {
      VH vs[3];
      int k = 0;
      for (const VH v : mesh_.fv_range(f)) vs[k++] = v;
      for (int i = 0; i < 3; ++i) vertex_vector(vs[i], x[i]);
      const double area = 0.5 * OpenMesh::cross(mesh_.point(vs[1]) - mesh_.point(vs[0]), mesh_.point(vs[2]) - mesh_.point(vs[0])).norm();
      // Plane weight (docs/decimate.md 2.1): GH97's area, each plane once, or the square
      // root of the area -- between the two, it keeps small features (low Hausdorff error)
      // without giving up the area weighting's low RMS error (tests/bench/RESULTS.md).
      const double wgt = opt_.weighting == Weighting::area ? area : opt_.weighting == Weighting::uniform ? 1.0 : std::sqrt(area);
      Quadric q = Quadric::triangle(x[0], x[1], x[2], n, wgt);
      q.set_weight(area);  // the area W of the error estimate either way
      for (const VH v : vs) q.add_to_packed(packed(v));
    }
    for (const EH e : mesh_.edges()) {
      const bool boundary = mesh_.is_boundary(e);
      const bool feature = !boundary && is_feature(e);
      if (!boundary && !feature) continue;
      (boundary ? st_.boundary_edges : st_.feature_edges) += 1;
      HH h = mesh_.halfedge_handle(e, 0);
      if (mesh_.is_boundary(h)) h = mesh_.opposite_halfedge_handle(h);
      const VH a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
      const bool lock = boundary ? opt_.lock_boundary : opt_.lock_features;
      if (lock) {
        locked_[static_cast<std::size_t>(a.idx())] = 1;
        locked_[static_cast<std::size_t>(b.idx())] = 1;
      }
      const OpenMesh::Vec3d d = mesh_.point(b) - mesh_.point(a);
      auto add_plane = [&](FH f) {
        OpenMesh::Vec3d pn = OpenMesh::cross(d, mesh_.calc_face_normal(f));
        const double l = pn.norm();
        if (!(l > 0)) return;
        pn /= l;
        const double p[3] = {mesh_.point(a)[0], mesh_.point(a)[1], mesh_.point(a)[2]};
        const double nn[3] = {pn[0], pn[1], pn[2]};
        const Quadric q = Quadric::position_plane(p, nn, n, opt_.constraint_weight * d.sqrnorm());
        q.add_to_packed(packed(a));
        q.add_to_packed(packed(b));
      };
      add_plane(mesh_.face_handle(h));
      if (feature) add_plane(mesh_.face_handle(mesh_.opposite_halfedge_handle(h)));
    }
    for (const char l : locked_) st_.locked_vertices += l ? 1 : 0;
  }

  // The quadric error is area-weighted; divided by the merged area it is a mean squared
  // distance, whose root is the length the --error bound compares (docs/decimate.md 2.3).
  double error_estimate_of(double cost, EH e) const {
    const VH a = mesh_.to_vertex_handle(mesh_.halfedge_handle(e, 0)), b = mesh_.from_vertex_handle(mesh_.halfedge_handle(e, 0));
    const double w = packed(a)[stride_ - 1] + packed(b)[stride_ - 1];
    return w > 0 ? std::sqrt(cost / w) : 0.0;
  }

  // Chooses the collapse direction and target point of edge e; cost in `plan`.
  bool choose_target(EH e, Plan& plan, double& cost) const {
    const HH h0 = mesh_.halfedge_handle(e, 0);
    const VH a = mesh_.from_vertex_handle(h0), b = mesh_.to_vertex_handle(h0);
    const bool la = locked_[static_cast<std::size_t>(a.idx())] != 0, lb = locked_[static_cast<std::size_t>(b.idx())] != 0;
    if (la && lb) return false;
    const int n = layout_.n;
    double qsum[Quadric::packed_size(max_dimension)];
    const double *qa = packed(a), *qb = packed(b);
    for (std::size_t i = 0; i < stride_; ++i) qsum[i] = qa[i] + qb[i];
    const PackedQuadric q{qsum, n};
    double xa[max_dimension], xb[max_dimension];
    vertex_vector(a, xa);
    vertex_vector(b, xb);
    if (la || lb || !opt_.optimal_placement) {
      // Locked end, or half-edge collapse: the survivor keeps its place.
      double ca = la || !lb ? q.evaluate(xa) : std::numeric_limits<double>::infinity();
      double cb = lb || !la ? q.evaluate(xb) : std::numeric_limits<double>::infinity();
      if (cb <= ca) { plan.h = h0; std::copy(xb, xb + n, plan.v); cost = cb; }
      else { plan.h = mesh_.opposite_halfedge_handle(h0); std::copy(xa, xa + n, plan.v); cost = ca; }
      return true;
    }
    plan.h = h0;
    if (q.minimise(plan.v)) {
      cost = q.evaluate(plan.v);
      return true;
    }
    // Singular quadric (flat or straight neighbourhood): the best of the ends and the
    // midpoint (GH97 section 4).
    double xm[max_dimension];
    for (int i = 0; i < n; ++i) xm[i] = 0.5 * (xa[i] + xb[i]);
    const double ca = q.evaluate(xa), cb = q.evaluate(xb), cm = q.evaluate(xm);
    if (cm < ca && cm < cb) { std::copy(xm, xm + n, plan.v); cost = cm; }
    else if (ca < cb) { std::copy(xa, xa + n, plan.v); cost = ca; }
    else { std::copy(xb, xb + n, plan.v); cost = cb; }
    return true;
  }

  void push(EH e) {
    Plan plan;
    double cost = 0;
    ++version_[static_cast<std::size_t>(e.idx())];
    if (!choose_target(e, plan, cost)) return;
    heap_.push({cost, static_cast<std::uint32_t>(e.idx()), version_[static_cast<std::size_t>(e.idx())]});
  }

  // No face around the two vertices may turn over (or past acos(min_normal_cos)) or
  // become degenerate when the survivor moves to p.
  bool flips(HH h, const OpenMesh::Vec3d& p) const {
    const VH from = mesh_.from_vertex_handle(h), to = mesh_.to_vertex_handle(h);
    const FH fl = mesh_.face_handle(h), fr = mesh_.face_handle(mesh_.opposite_halfedge_handle(h));
    for (const VH moved : {from, to}) {
      for (const HH oh : mesh_.voh_range(moved)) {
        const FH f = mesh_.face_handle(oh);
        if (!f.is_valid() || f == fl || f == fr) continue;
        const VH v1 = mesh_.to_vertex_handle(oh), v2 = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(oh));
        const OpenMesh::Vec3d& p1 = mesh_.point(v1);
        const OpenMesh::Vec3d& p2 = mesh_.point(v2);
        const OpenMesh::Vec3d& p0 = mesh_.point(moved);
        const OpenMesh::Vec3d n_old = OpenMesh::cross(p1 - p0, p2 - p0);
        const OpenMesh::Vec3d n_new = OpenMesh::cross(p1 - p, p2 - p);
        const double lo = n_old.norm(), ln = n_new.norm();
        if (!(ln > 1e-14 * (lo + ln)) ) return true;
        if (lo > 0 && OpenMesh::dot(n_old, n_new) < opt_.min_normal_cos * lo * ln) return true;
      }
    }
    return false;
  }

  bool plan_collapse(EH e, Plan& plan) {
    double cost = 0;
    if (!choose_target(e, plan, cost)) { ++st_.rejected_locked; return false; }
    plan.estimate = error_estimate_of(cost, e);
    const OpenMesh::Vec3d p(plan.v[0], plan.v[1], plan.v[2]);
    HH tries[2] = {plan.h, mesh_.opposite_halfedge_handle(plan.h)};
    const bool fixed_end = locked_[static_cast<std::size_t>(mesh_.to_vertex_handle(plan.h).idx())] ||
                           !opt_.optimal_placement;
    bool link_failed = false;
    for (int k = 0; k < (fixed_end ? 1 : 2); ++k) {
      if (!mesh_.is_collapse_ok(tries[k])) { link_failed = true; continue; }
      if (flips(tries[k], p)) continue;
      plan.h = tries[k];
      return true;
    }
    ++(link_failed ? st_.rejected_link : st_.rejected_flip);
    return false;
  }

  void collapse(const Plan& plan) {
    const VH from = mesh_.from_vertex_handle(plan.h), to = mesh_.to_vertex_handle(plan.h);
    const double* qf = packed(from);
    double* qt = packed(to);
    for (std::size_t i = 0; i < stride_; ++i) qt[i] += qf[i];
    mesh_.collapse(plan.h);
    store_vector(to, plan.v);
    for (const EH e : mesh_.ve_range(to)) push(e);
  }

  TriMesh& mesh_;
  const SimplifyOptions& opt_;
  SimplifyStats& st_;
  Layout layout_;
  double* packed(VH v) { return quadric_.data() + static_cast<std::size_t>(v.idx()) * stride_; }
  const double* packed(VH v) const { return quadric_.data() + static_cast<std::size_t>(v.idx()) * stride_; }
  std::vector<double> quadric_;  // packed quadric per vertex (Quadric::packed_size)
  std::size_t stride_ = 0;
  std::vector<char> locked_;
  std::vector<std::uint32_t> version_;
  std::priority_queue<Candidate> heap_;
};

}  // namespace

Mesh simplify(const Mesh& input, const SimplifyOptions& options, SimplifyStats* stats) {
  SimplifyStats local;
  SimplifyStats& st = stats ? *stats : local;
  st = SimplifyStats{};
  st.input_faces = input.n_faces();
  st.input_vertices = input.n_vertices();
  for (const auto v : input.vertices()) {
    const auto& p = input.point(v);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw bad_input("vertex {} has a non-finite coordinate", v.idx());
  }
  // Copy into a triangle mesh (polygons as fans), with the attributes the input has.
  TriMesh tri;
  const bool vn = input.has_vertex_normals(), vc = input.has_vertex_colors(), vt = input.has_vertex_texcoords2D();
  const bool fc = input.has_face_colors(), fn = input.has_face_normals();
  if (vn) tri.request_vertex_normals();
  if (vc) tri.request_vertex_colors();
  if (vt) tri.request_vertex_texcoords2D();
  if (fc) tri.request_face_colors();
  if (fn) tri.request_face_normals();
  tri.request_vertex_status();
  tri.request_edge_status();
  tri.request_halfedge_status();
  tri.request_face_status();
  for (const auto v : input.vertices()) {
    const VH w = tri.add_vertex(input.point(v));
    if (vn) tri.set_normal(w, input.normal(v));
    if (vc) tri.set_color(w, input.color(v));
    if (vt) tri.set_texcoord2D(w, input.texcoord2D(v));
  }
  std::vector<VH> corner;
  for (const auto f : input.faces()) {
    corner.clear();
    for (const auto v : input.fv_range(f)) corner.push_back(VH(v.idx()));
    if (corner.size() > 3) ++st.triangulated_polygons;
    for (std::size_t i = 1; i + 1 < corner.size(); ++i) {
      const FH g = tri.add_face(corner[0], corner[i], corner[i + 1]);
      if (!g.is_valid()) throw bad_input("face {} cannot be added to a manifold triangle mesh", f.idx());
      if (fc) tri.set_color(g, input.color(f));
      if (fn) tri.set_normal(g, input.normal(f));
    }
  }
  Engine engine(tri, options, st);
  engine.run();
  tri.garbage_collection();
  // Back to fest's polygon mesh type, attributes included.
  Mesh out;
  if (vn) out.request_vertex_normals();
  if (vc) out.request_vertex_colors();
  if (vt) out.request_vertex_texcoords2D();
  if (fc) out.request_face_colors();
  if (fn) out.request_face_normals();
  for (const VH v : tri.vertices()) {
    const auto w = out.add_vertex(tri.point(v));
    if (vn) out.set_normal(w, tri.normal(v));
    if (vc) out.set_color(w, tri.color(v));
    if (vt) out.set_texcoord2D(w, tri.texcoord2D(v));
  }
  for (const FH f : tri.faces()) {
    std::vector<Mesh::VertexHandle> vs;
    for (const VH v : tri.fv_range(f)) vs.push_back(Mesh::VertexHandle(v.idx()));
    const auto g = out.add_face(vs);
    if (fc) out.set_color(g, tri.color(f));
    if (fn) out.set_normal(g, tri.normal(f));
  }
  st.output_faces = out.n_faces();
  st.output_vertices = out.n_vertices();
  return out;
}

}  // namespace fest::decimate

// Foreign predicates of line tracking (the optic nerves): tubularity, a tracking cost,
// the minimum-cost path and what rules measure on it, and the simple geometric masks
// (balls, boxes) that place its ends.
#include <algorithm>
#include <cmath>

#include "segbrain/morphology.hpp"
#include "segbrain/operator_args.hpp"
#include "segbrain/tracking.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain {
namespace {

Polarity polarity_of(const Term& t) {
  if (is_atom(t, "bright")) return Polarity::bright;
  if (is_atom(t, "dark")) return Polarity::dark;
  if (is_atom(t, "any")) return Polarity::any;
  throw bad_input("polarity must be bright, dark or any, got {}", to_string(deref(t)));
}

// Voxels within r_mm of the point (at least the voxel nearest to it when inside the grid).
Mask ball_mask(const Grid& g, const std::vector<double>& c, double r_mm) {
  Mask m(g.size(), 0);
  long near[3];
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    near[a] = std::lround(c[a] / g.spacing[a]);
    inside = inside && near[a] >= 0 && near[a] < long(g.n[a]);
  }
  if (inside) m[g.index(std::size_t(near[0]), std::size_t(near[1]), std::size_t(near[2]))] = 1;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        const double d[3] = {double(x) * g.spacing[0] - c[0], double(y) * g.spacing[1] - c[1], double(z) * g.spacing[2] - c[2]};
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= r_mm * r_mm) m[g.index(x, y, z)] = 1;
      }
  return m;
}

}  // namespace

void Workspace::register_tracking_operators(Engine& engine) {
  using namespace args;
  engine.register_foreign("vesselness", 5, "+Img, +SigmaMM, +bright|dark|any, +Within|all, -Out",
      "Frangi-type Hessian tubularity in [0, 1), computed in the bounding box of Within",
      [this](Engine& e, const std::vector<Term>& a) {
        const double sigma = e.eval(a[1]);
        if (!(sigma > 0)) throw bad_input("vesselness: sigma must be > 0, got {}", sigma);
        Mask empty;
        const Mask& within = is_atom(a[3], "all") ? empty : mask(name_of(a[3]));
        return create(e, a[4], image_object(vesselness(grid_, image(name_of(a[0])), sigma, polarity_of(a[2]), within)));
      });
  engine.register_foreign("tracking_cost", 6, "+Vesselness, +Img, +Lo, +Hi, +Penalty, -Cost",
      "1 / (0.05 + vesselness), times 1 + Penalty where the intensity lies outside [Lo, Hi]",
      [this](Engine& e, const std::vector<Term>& a) {
        const Image& v = image(name_of(a[0]));
        const Image& img = image(name_of(a[1]));
        const double lo = e.eval(a[2]), hi = e.eval(a[3]), pen = e.eval(a[4]);
        if (!(pen >= 0)) throw bad_input("tracking_cost: penalty must be >= 0, got {}", pen);
        Image c(v.size());
        for (std::size_t i = 0; i < c.size(); ++i)
          c[i] = static_cast<float>(1.0 / (0.05 + std::max(0.0f, v[i])) * (img[i] >= lo && img[i] <= hi ? 1.0 : 1.0 + pen));
        return create(e, a[5], image_object(std::move(c)));
      });
  engine.register_foreign("line_track", 4, "+Cost, +From, +To, -Path",
      "minimum-cost 26-connected path (Dijkstra) from a mask to a mask, in their bounding box grown by 10 mm; "
      "fails when To cannot be reached",
      [this](Engine& e, const std::vector<Term>& a) {
        std::vector<std::size_t> p = line_track(grid_, image(name_of(a[0])), mask(name_of(a[1])), mask(name_of(a[2])), 10.0);
        if (p.empty()) return false;
        Object o = mask_object(Mask(grid_.size(), 0));
        for (std::size_t i : p) o.mask[i] = 1;
        const double len = path_length_mm(grid_, p, 4);
        e.measure() = {{"path_length_mm", len}, {"path_voxels", double(p.size())}};
        o.path = std::move(p);
        return create(e, a[3], std::move(o));
      });
  engine.register_foreign("path_length_mm", 2, "+Path, -L", "length of a tracked path (polyline through every 4th voxel)",
      [this](Engine& e, const std::vector<Term>& a) {
        const Object& o = get(name_of(a[0]));
        if (o.path.empty()) throw bad_input("path_length_mm: '{}' is not a tracked path", name_of(a[0]));
        const double len = path_length_mm(grid_, o.path, 4);
        e.measure() = {{"path_length_mm", len}};
        return e.unify(a[1], make_real(len));
      });
  engine.register_foreign("path_point", 3, "+Path, +first|last, -[R,A,S]", "position (mm) of the first or last voxel of a tracked path",
      [this](Engine& e, const std::vector<Term>& a) {
        const Object& o = get(name_of(a[0]));
        if (o.path.empty()) throw bad_input("path_point: '{}' is not a tracked path", name_of(a[0]));
        const bool first = is_atom(a[1], "first");
        if (!first && !is_atom(a[1], "last")) throw bad_input("path_point: which end, first or last?");
        return e.unify(a[2], number_list(position_mm(grid_, first ? o.path.front() : o.path.back())));
      });
  engine.register_foreign("ball", 3, "+[R,A,S], +RadiusMM, -Mask", "voxels within RadiusMM of the point (at least the nearest voxel)",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[2], mask_object(ball_mask(grid_, numbers(e, a[0], 3, "a point [R, A, S]"), e.eval(a[1]))));
      });
  engine.register_foreign("box", 2, "+[R0,R1,A0,A1,S0,S1], -Mask", "voxels whose position (mm) lies in the box",
      [this](Engine& e, const std::vector<Term>& a) {
        auto b = numbers(e, a[0], 6, "a box [R0, R1, A0, A1, S0, S1]");
        const Grid& g = grid_;
        Mask m(g.size(), 0);
        for (std::size_t z = 0; z < g.n[2]; ++z)
          for (std::size_t y = 0; y < g.n[1]; ++y)
            for (std::size_t x = 0; x < g.n[0]; ++x) {
              const double p[3] = {double(x) * g.spacing[0], double(y) * g.spacing[1], double(z) * g.spacing[2]};
              bool in = true;
              for (int ax = 0; ax < 3; ++ax) in = in && p[ax] >= b[2 * ax] && p[ax] <= b[2 * ax + 1];
              m[g.index(x, y, z)] = in;
            }
        return create(e, a[1], mask_object(std::move(m)));
      });
  engine.register_foreign("component_centroids", 3, "+Mask, +Conn, -[[R,A,S], ...]", "centroids (mm) of the connected components, by increasing R",
      [this](Engine& e, const std::vector<Term>& a) {
        const int conn = static_cast<int>(e.eval(a[1]));
        if (conn != 6 && conn != 18 && conn != 26) throw bad_input("component_centroids: connectivity 6, 18 or 26, got {}", conn);
        Components cc = connected_components(grid_, mask(name_of(a[0])), conn);
        std::vector<std::vector<double>> sums(cc.size.size(), std::vector<double>(3, 0.0));
        for (std::size_t i = 0; i < cc.label.size(); ++i)
          if (cc.label[i]) {
            auto p = position_mm(grid_, i);
            for (int ax = 0; ax < 3; ++ax) sums[cc.label[i]][ax] += p[ax];
          }
        std::vector<std::vector<double>> cents;
        for (std::size_t id = 1; id < cc.size.size(); ++id) {
          for (auto& v : sums[id]) v /= double(cc.size[id]);
          cents.push_back(sums[id]);
        }
        std::stable_sort(cents.begin(), cents.end(), [](const auto& p, const auto& q) { return p[0] < q[0]; });
        std::vector<Term> items;
        for (const auto& c : cents) items.push_back(number_list(c));
        e.measure() = {{"components", double(cents.size())}};
        return e.unify(a[2], make_list(items));
      });
}

}  // namespace fest::segbrain

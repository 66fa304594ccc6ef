#include "radiosity/form_factors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/parallel_for.hpp"
#include "core/rng.hpp"
#include "radiosity/polygon_ff.hpp"
#include "radiosity/scene.hpp"

namespace fest::radiosity {

const char* engine_name(Engine e) {
  switch (e) {
    case Engine::hemicube: return "hemicube";
    case Engine::raycast: return "raycast";
    case Engine::analytic: return "analytic";
    default: return "hybrid";
  }
}

namespace {

double unit(std::uint64_t x) { return static_cast<double>(splitmix64_mix(x) >> 11) * (1.0 / 9007199254740992.0); }

// S stratified points on a polygon (a ceil(sqrt S)^2 grid, jittered by a hash of the
// polygon's id so that every run draws the same points).
std::vector<Eigen::Vector3d> stratified(const Polygon& p, int samples, std::uint64_t seed) {
  const int m = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples)) - 1e-9)));
  std::vector<Eigen::Vector3d> out;
  for (int j = 0; j < m && static_cast<int>(out.size()) < samples; ++j)
    for (int i = 0; i < m && static_cast<int>(out.size()) < samples; ++i) {
      const std::uint64_t h = seed * 1000003ull + static_cast<std::uint64_t>(j * m + i) * 2;
      out.push_back(p.sample((i + unit(h)) / m, (j + unit(h + 1)) / m));
    }
  return out;
}

}  // namespace

FormFactors::FormFactors(const Model& model, const FormFactorOptions& options) : model_(model), options_(options) {
  if (options_.engine == Engine::hemicube || options_.engine == Engine::hybrid)
    hemicube_ = std::make_unique<Hemicube>(options_.hemicube_res);
  bvh_ = Bvh(model_.occluders);  // shadow rays of the ray engines and of adaptive gathering
  offset_ = 1e-4 * model_.diagonal;
  refresh();
}

void FormFactors::refresh() {
  active_ = model_.active_elements();
  items_.clear();
  for (int e : active_) items_.push_back(&model_.elements[e].poly);
}

std::vector<Eigen::Vector3d> FormFactors::shooter_samples(int i) const {
  return stratified(model_.patches[i].poly, options_.samples, static_cast<std::uint64_t>(i) + 1);
}

double FormFactors::ray_ff(const Eigen::Vector3d& y, const Eigen::Vector3d& n, int i,
                           const std::vector<Eigen::Vector3d>& pts, bool analytic) const {
  const Patch& sh = model_.patches[i];
  const double da = sh.area / static_cast<double>(pts.size());
  const Eigen::Vector3d ys = y + offset_ * n;
  double sum = 0;
  int front = 0, visible = 0;
  for (const Eigen::Vector3d& x : pts) {
    const Eigen::Vector3d r = x - y;
    const double r2 = r.squaredNorm();
    if (r2 <= 0) continue;
    const double len = std::sqrt(r2);
    const double cy = n.dot(r) / len, cs = -sh.normal.dot(r) / len;
    if (cy <= 0 || cs <= 0) continue;
    ++front;
    if (bvh_.occluded(ys, x + offset_ * sh.normal)) continue;
    ++visible;
    sum += cy * cs * da / (M_PI * r2 + da);
  }
  if (!analytic) return sum;
  if (front == 0) return 0;
  return point_polygon_ff(y, n, sh.poly) * visible / front;
}

double FormFactors::point_to_patch(const Eigen::Vector3d& y, const Eigen::Vector3d& n, int k) const {
  return ray_ff(y, n, k, shooter_samples(k), true);
}

void FormFactors::shoot(int i, std::vector<double>& recv, std::vector<double>& row) {
  const Patch& sh = model_.patches[i];
  recv.assign(model_.elements.size(), 0.0);
  row.assign(model_.patches.size(), 0.0);
  if (options_.engine == Engine::hybrid) {
    draw_.assign(items_.size(), 1);
    for (std::size_t k = 0; k < active_.size(); ++k)
      if (model_.elements[active_[k]].patch == i) draw_[k] = 0;
    hemicube_->project(sh.centroid, sh.normal, items_, draw_, 1e-9 * model_.diagonal, options_.threads, ff_, &cover_, &vis_);
    parallel_for(active_.size(), options_.threads, [&](std::size_t k) {
      if (!draw_[k]) return;
      const Element& el = model_.elements[active_[k]];
      // Only the shooter's front side emits.
      if ((el.centroid - sh.centroid).dot(sh.normal) <= 0) return;
      double visible;
      if (cover_[k] > 0) visible = std::min(1.0, vis_[k] / cover_[k]);
      else if ((sh.centroid - el.centroid).dot(el.normal) <= 0) return;
      else visible = bvh_.occluded(el.centroid + offset_ * el.normal, sh.centroid + offset_ * sh.normal) ? 0.0 : 1.0;
      if (visible <= 0) return;
      recv[active_[k]] = visible * point_polygon_ff(el.centroid, el.normal, sh.poly);
    });
    for (int e : active_) {
      const Element& el = model_.elements[e];
      row[el.patch] += el.area * recv[e] / sh.area;
    }
    return;
  }
  if (options_.engine == Engine::hemicube) {
    draw_.assign(items_.size(), 1);
    for (std::size_t k = 0; k < active_.size(); ++k)
      if (model_.elements[active_[k]].patch == i) draw_[k] = 0;
    hemicube_->project(sh.centroid, sh.normal, items_, draw_, 1e-9 * model_.diagonal, options_.threads, ff_);
    for (std::size_t k = 0; k < active_.size(); ++k) {
      if (ff_[k] == 0) continue;
      const Element& el = model_.elements[active_[k]];
      recv[active_[k]] = std::min(1.0, ff_[k] * sh.area / el.area);
      row[el.patch] += ff_[k];
    }
    return;
  }
  const bool analytic = options_.engine == Engine::analytic;
  const std::vector<Eigen::Vector3d> pts = shooter_samples(i);
  parallel_for(active_.size(), options_.threads, [&](std::size_t k) {
    const Element& el = model_.elements[active_[k]];
    if (el.patch == i) return;
    if ((el.centroid - sh.centroid).dot(sh.normal) <= 0 && [&] {
          for (int c = 0; c < el.poly.n; ++c)
            if ((el.poly.p[c] - sh.centroid).dot(sh.normal) > 0) return false;
          return true;
        }())
      return;  // wholly behind the shooter
    double sum = 0;
    for (int c = 0; c < el.poly.n; ++c) {
      // Corners pulled 0.1 % towards the centroid: a corner on the line where two walls
      // meet would otherwise sit exactly on the neighbour's edge.
      const Eigen::Vector3d y = el.poly.p[c] + 1e-3 * (el.centroid - el.poly.p[c]);
      sum += ray_ff(y, el.normal, i, pts, analytic);
    }
    recv[active_[k]] = sum / el.poly.n;
  });
  for (int e : active_) {
    const Element& el = model_.elements[e];
    row[el.patch] += el.area * recv[e] / sh.area;
  }
}

double polygon_form_factor(const Polygon& a, const Polygon& b, const FormFactorOptions& options, int cells) {
  // Without occluders the hybrid engine's value is the analytic one.
  if (options.engine == Engine::analytic || options.engine == Engine::hybrid) return polygon_polygon_ff(a, b);
  const std::vector<Polygon> parts = split_polygon(a, a.longest_edge() / cells);
  if (options.engine == Engine::hemicube) {
    Hemicube cube(options.hemicube_res);
    std::vector<Polygon> targets = split_polygon(b, b.longest_edge() / cells);
    std::vector<const Polygon*> items;
    for (const Polygon& t : targets) items.push_back(&t);
    std::vector<std::uint8_t> draw(items.size(), 1);
    std::vector<double> ff;
    double sum = 0, area = 0;
    for (const Polygon& p : parts) {
      const double scale = std::max(a.longest_edge(), b.longest_edge());
      cube.project(p.centroid(), a.normal(), items, draw, 1e-9 * scale, options.threads, ff);
      double f = 0;
      for (double v : ff) f += v;
      sum += p.area() * f;
      area += p.area();
    }
    return sum / area;
  }
  // Ray engine without occluders: Wallace's sum from each part's corners.
  const std::vector<Eigen::Vector3d> pts = stratified(b, options.samples, 1);
  const Eigen::Vector3d nb = b.normal(), na = a.normal();
  const double da = b.area() / static_cast<double>(pts.size());
  double sum = 0, area = 0;
  for (const Polygon& p : parts) {
    double f = 0;
    const Eigen::Vector3d c = p.centroid();
    for (int k = 0; k < p.n; ++k) {
      const Eigen::Vector3d y = p.p[k] + 1e-3 * (c - p.p[k]);
      for (const Eigen::Vector3d& x : pts) {
        const Eigen::Vector3d r = x - y;
        const double r2 = r.squaredNorm(), len = std::sqrt(r2);
        const double cy = na.dot(r) / len, cs = -nb.dot(r) / len;
        if (cy > 0 && cs > 0) f += cy * cs * da / (M_PI * r2 + da);
      }
    }
    sum += p.area() * f / p.n;
    area += p.area();
  }
  return sum / area;
}

}  // namespace fest::radiosity

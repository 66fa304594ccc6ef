#include "radiosity/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "radiosity/scene.hpp"
#include "radiosity/vertex_values.hpp"

namespace fest::radiosity {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double unshot_total(const Model& m) {
  double u = 0;
  for (const Patch& p : m.patches) u += p.area * p.U.abs().sum();
  return u;
}

}  // namespace

const char* solver_name(Solver s) {
  switch (s) {
    case Solver::pr: return "pr";
    case Solver::sor: return "sor";
    case Solver::overshoot: return "overshoot";
    default: return "orpr";
  }
}

SolveStats solve(Model& model, FormFactors& ff, const SolveOptions& options) {
  SolveStats stats;
  const auto start = Clock::now();
  double emitted = 0;
  for (const Patch& p : model.patches) emitted += p.area * p.E.sum();
  const double omega = options.omega >= 0 ? options.omega : options.solver == Solver::sor ? 1.5 : 1.0;
  Solver solver = options.solver;
  std::vector<double> recv, row;
  long total = 0;
  for (int level = 0; level <= options.levels; ++level) {
    if (level > 0) {
      const auto t = Clock::now();
      const long split = subdivide(model, ff, options.grad, options.min_element, options.threads);
      ff.refresh();
      stats.subdivision_seconds += since(t);
      if (split == 0) break;
    }
    stats.elements_per_level.push_back(static_cast<long>(model.active_elements().size()));
    const long max_shots = options.max_shots > 0 ? options.max_shots : 10 * static_cast<long>(model.patches.size());
    double last = unshot_total(model);
    int growing = 0;
    long shots = 0;
    bool converged = emitted <= 0 || last <= options.tol * emitted;
    while (!converged && shots < max_shots) {
      // 1. the shooter: largest A_p sum |U_p|, ties to the lowest id.
      int i = 0;
      double best = -1;
      for (std::size_t p = 0; p < model.patches.size(); ++p) {
        const double w = model.patches[p].area * model.patches[p].U.abs().sum();
        if (w > best) {
          best = w;
          i = static_cast<int>(p);
        }
      }
      // 2. its form factors.
      auto t = Clock::now();
      ff.shoot(i, recv, row);
      stats.visibility_seconds += since(t);
      t = Clock::now();
      Patch& sh = model.patches[i];
      // 3. the shot amount.
      Rgb s = sh.U;
      double w_eff = 1;
      if (solver == Solver::sor) {
        s = omega * sh.U;
        w_eff = omega;
      } else if (solver == Solver::overshoot || solver == Solver::orpr) {
        Rgb gather = Rgb::Zero();
        for (std::size_t k = 0; k < model.patches.size(); ++k) {
          if (row[k] == 0) continue;
          gather += row[k] * (solver == Solver::overshoot ? model.patches[k].U.max(0.0) : model.patches[k].U);
        }
        const double wg = solver == Solver::orpr ? omega : 1.0;
        s = sh.U + wg * sh.rho * gather;
        w_eff = wg;
      }
      // 4. distribute to every element outside the shooter.
      ShotRecord rec;
      for (std::size_t e = 0; e < model.elements.size(); ++e) {
        if (recv[e] == 0) continue;
        Element& el = model.elements[e];
        Patch& rp = model.patches[el.patch];
        const Rgb h = recv[e] * s;
        const Rgb db = rp.rho * h;
        el.H += h;
        el.B += db;
        rp.U += (el.area / rp.area) * db;
        rp.B += (el.area / rp.area) * db;
        rec.received_energy += el.area * recv[e] * s.abs().sum();
      }
      // 5. the shooter's own account.
      sh.U -= s;
      sh.S += s;
      ++shots;
      ++total;
      const double now = unshot_total(model);
      if (!std::isfinite(now)) throw runtime_failure("radiosity diverged (not a number after shot {})", total);
      rec.shot = total;
      rec.patch = i;
      rec.object = sh.object;
      rec.unshot_fraction = emitted > 0 ? now / emitted : 0;
      rec.omega = w_eff;
      rec.shot_energy = sh.area * s.abs().sum();
      rec.level = level;
      for (double r : row) rec.row_sum += r;
      stats.solve_seconds += since(t);
      rec.seconds = since(start);
      if (options.on_shot) options.on_shot(rec, model);
      // Safeguard: 50 shots in a row that increased the unshot total -> plain PR.
      growing = now > last ? growing + 1 : 0;
      last = now;
      if (growing >= 50 && solver != Solver::pr) {
        solver = Solver::pr;
        stats.fell_back = true;
      }
      converged = now <= options.tol * emitted;
    }
    stats.shots_per_level.push_back(shots);
    stats.converged = converged;
  }
  stats.shots = total;
  stats.unshot_fraction = emitted > 0 ? unshot_total(model) / emitted : 0;
  return stats;
}

long subdivide(Model& model, const FormFactors& ff, double grad, double min_element, int threads) {
  const VertexValues vv = vertex_values(model, 20.0);
  // B_max over the reflectors: an emitter's own exitance would make every reflected
  // gradient look flat.
  double ymax = 0;
  for (std::size_t v = 0; v < vv.B.size(); ++v)
    if ((model.objects[vv.object[v]].emission == 0).all()) ymax = std::max(ymax, luminance(vv.B[v]));
  if (!(ymax > 0)) return 0;
  // Elements to split: the largest luminance step along one of their edges.
  std::vector<int> split;
  const std::vector<int> active = model.active_elements();
  for (std::size_t k = 0; k < active.size(); ++k) {
    const int e = active[k];
    const Element& el = model.elements[e];
    const auto& c = vv.element_corners[k];
    double g = 0;
    for (int a = 0; a < el.poly.n; ++a) {
      const int b = (a + 1) % el.poly.n;
      g = std::max(g, std::abs(luminance(vv.B[c[a]]) - luminance(vv.B[c[b]])) / ymax);
    }
    if (g > grad && el.poly.longest_edge() > min_element) split.push_back(e);
  }
  // Children gather from every patch that has shot: B_c = E_c + rho_c sum_i F_{c->i} S_i.
  std::vector<int> shooters;
  for (std::size_t p = 0; p < model.patches.size(); ++p)
    if ((model.patches[p].S != 0).any()) shooters.push_back(static_cast<int>(p));
  std::vector<std::vector<Element>> children(split.size());
  parallel_for(split.size(), threads, [&](std::size_t k) {
    const Element& parent = model.elements[split[k]];
    const Patch& pt = model.patches[parent.patch];
    for (const Polygon& q : split_in_four(parent.poly)) {
      Element c;
      c.poly = q;
      c.area = q.area();
      c.centroid = q.centroid();
      c.normal = parent.normal;
      c.patch = parent.patch;
      c.level = parent.level + 1;
      Rgb h = Rgb::Zero();
      for (int i : shooters) {
        if (i == parent.patch) continue;
        const double f = ff.point_to_patch(c.centroid, c.normal, i);
        if (f > 0) h += f * model.patches[i].S;
      }
      c.H = h;
      c.B = pt.E + pt.rho * h;
      children[k].push_back(c);
    }
  });
  for (std::size_t k = 0; k < split.size(); ++k) {
    const int e = split[k];
    Element& parent = model.elements[e];
    parent.active = false;
    Patch& pt = model.patches[parent.patch];
    pt.elements.erase(std::find(pt.elements.begin(), pt.elements.end(), e));
    const Rgb parent_b = parent.B;
    for (const Element& c : children[k]) {
      // The patch's unshot takes the change the children bring: U_p += (A_c/A_p)(B_c - B_parent).
      const Rgb d = (c.area / pt.area) * (c.B - parent_b);
      pt.U += d;
      pt.B += d;
      pt.elements.push_back(static_cast<int>(model.elements.size()));
      model.elements.push_back(c);
    }
  }
  return static_cast<long>(split.size());
}

}  // namespace fest::radiosity

#include "fluidsim/simulator.hpp"

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "fluidsim/advection.hpp"
#include "fluidsim/operators.hpp"

namespace fest::fluidsim {

namespace {

using Clock = SteadyClock;

// Calls f(n, weight) for every node of a source region.
template <typename F>
void for_region(const Layout& L, const Source& src, F&& f) {
  std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};
  double reach = 0.0;
  if (src.shape == Source::Shape::box) {
    for (int a = 0; a < L.dim; ++a) {
      lo[a] = static_cast<int>(std::ceil(src.min[a]));
      hi[a] = static_cast<int>(std::floor(src.max[a]));
    }
  } else {
    reach = src.shape == Source::Shape::sphere ? src.radius : 3.0 * src.radius;
    for (int a = 0; a < L.dim; ++a) {
      lo[a] = std::max(0, static_cast<int>(std::ceil(src.centre[a] - reach)));
      hi[a] = std::min(L.size[a] - 1, static_cast<int>(std::floor(src.centre[a] + reach)));
    }
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        double w = 1.0;
        if (src.shape != Source::Shape::box) {
          const double d[3] = {i - src.centre[0], j - src.centre[1], L.dim == 3 ? k - src.centre[2] : 0.0};
          const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
          if (src.shape == Source::Shape::sphere) {
            if (r2 > src.radius * src.radius) continue;
          } else {
            w = std::exp(-0.5 * r2 / (src.radius * src.radius));
          }
        }
        f(L.index(i, j, k), w);
      }
}

bool active_at(const Source& src, double t) { return t >= src.start && t < src.end; }

// Whether every value is finite (a logical AND: the same answer for any split).
bool all_finite(const Field& f) {
  bool ok = true;
  const double* v = f.data();
#pragma omp parallel for schedule(static) reduction(&& : ok) if (f.size() >= kParallelNodes)
  for (std::size_t n = 0; n < f.size(); ++n) ok = ok && std::isfinite(v[n]);
  return ok;
}

void check_finite(const Layout& L, const State& s) {
  for (int c = 0; c < L.dim; ++c)
    if (!all_finite(s.u[c])) throw runtime_failure("state became non-finite at step {} (velocity)", s.step);
  for (const Field& f : s.s)
    if (!all_finite(f)) throw runtime_failure("state became non-finite at step {} (scalar)", s.step);
}

// `to` = `from`, copied by the team (fresh or resized buffers only where sizes differ).
void parallel_copy(const Field& from, Field& to) {
  if (to.size() != from.size()) to.resize(from.size());
  const double* a = from.data();
  double* b = to.data();
#pragma omp parallel for schedule(static) if (from.size() >= kParallelNodes)
  for (std::size_t n = 0; n < from.size(); ++n) b[n] = a[n];
}

// A buffer of n values whose contents do not matter (every value is written next).
void ensure_size(Field& f, std::size_t n) {
  if (f.size() != n) f.assign(n, 0.0);
}

}  // namespace

Simulator::Simulator(const Scene& scene, const SimOptions& options)
    : scene_(scene), options_(options), layout_(scene.layout()) {
  ProjectionOptions po = options_.projection;
  po.compact = options_.stam03;
  projector_ = std::make_unique<Projector>(layout_, po);
}

Simulator::~Simulator() = default;

void taylor_green(const Layout& L, Velocity& u) {
  for (int k = 0; k < L.size[2]; ++k)
    for (int j = 0; j < L.size[1]; ++j)
      for (int i = 0; i < L.size[0]; ++i) {
        const double x = 2.0 * M_PI * i / L.size[0], y = 2.0 * M_PI * j / L.size[1];
        u[0][L.index(i, j, k)] = std::sin(x) * std::cos(y);
        u[1][L.index(i, j, k)] = -std::cos(x) * std::sin(y);
      }
}

void abc_flow(const Layout& L, Velocity& u) {
  for (int k = 0; k < L.size[2]; ++k)
    for (int j = 0; j < L.size[1]; ++j)
      for (int i = 0; i < L.size[0]; ++i) {
        const double x = 2.0 * M_PI * i / L.size[0], y = 2.0 * M_PI * j / L.size[1], z = 2.0 * M_PI * k / L.size[2];
        const std::size_t n = L.index(i, j, k);
        u[0][n] = std::sin(z) + std::cos(y);
        u[1][n] = std::sin(x) + std::cos(z);
        u[2][n] = std::sin(y) + std::cos(x);
      }
}

State Simulator::initial_state(const State* given) const {
  State s;
  for (int c = 0; c < 3; ++c) s.u[c] = c < layout_.dim ? layout_.zeros() : Field();
  const std::string& kind = scene_.init.kind;
  if (given) {
    const std::string where = scene_.init.file.empty() ? std::string("init") : scene_.init.file;
    auto check = [&](const Field& f) {
      if (f.size() != layout_.count())
        throw bad_input("init file has {} nodes, the scene's grid stores {} ({})", f.size(), layout_.count(), where);
      for (double v : f)
        if (!std::isfinite(v)) throw bad_input("init file holds non-finite values ({})", where);
    };
    for (int c = 0; c < layout_.dim; ++c) {
      check(given->u[c]);
      s.u[c] = given->u[c];
    }
    if (given->s.size() != scene_.scalars.size())
      throw bad_input("init gives {} scalars, the scene has {} ({})", given->s.size(), scene_.scalars.size(), where);
    for (const Field& f : given->s) check(f);
    s.s = given->s;
    enforce_walls(layout_, s.u, scene_.no_slip);
    projector_->project(s.u);
    return s;
  }
  if (kind == "file") throw bad_input("init names a file ({}) but no fields were read from it", scene_.init.file);
  if (kind == "taylor-green") {
    taylor_green(layout_, s.u);
  } else if (kind == "abc") {
    if (layout_.dim != 3) throw bad_input("init \"abc\" needs a 3-D grid");
    abc_flow(layout_, s.u);
  } else if (kind == "noise") {
    std::mt19937_64 rng(scene_.init.seed);
    std::uniform_real_distribution<double> U(-scene_.init.amp, scene_.init.amp);
    for (int c = 0; c < layout_.dim; ++c)
      for (double& v : s.u[c]) v = U(rng);
    projector_->project(s.u);
  }
  enforce_walls(layout_, s.u, scene_.no_slip);
  for (const ScalarSpec& sc : scene_.scalars) s.s.emplace_back(layout_.count(), sc.init);
  return s;
}

void Simulator::add_forces(const State& st, double dt, Velocity& u) const {
  const Layout& L = layout_;
  for (const Force& f : scene_.forces) {
    switch (f.type) {
      case Force::Type::buoyancy: {
        std::size_t which = 0;
        for (std::size_t i = 0; i < scene_.scalars.size(); ++i)
          if (scene_.scalars[i].name == f.scalar) which = i;
        const Field& s = st.s[which];
        for (int c = 0; c < L.dim; ++c) {
          if (f.up[c] == 0.0) continue;
          const double k = dt * f.beta * f.up[c];
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
          for (std::size_t n = 0; n < s.size(); ++n) u[c][n] += k * (s[n] - f.ambient);
        }
        break;
      }
      case Force::Type::gravity:
      case Force::Type::constant:
        for (int c = 0; c < L.dim; ++c) {
          double* v = u[c].data();
          const double add = dt * f.value[c];
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
          for (std::size_t n = 0; n < L.count(); ++n) v[n] += add;
        }
        break;
      case Force::Type::vortex: {
        // Swirl about the axis `up` through `centre`: f = strength (up x r) exp(-|r|^2/R^2).
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
        for (int k = 0; k < L.size[2]; ++k)
          for (int j = 0; j < L.size[1]; ++j)
            for (int i = 0; i < L.size[0]; ++i) {
              const double r[3] = {i - f.centre[0], j - f.centre[1], L.dim == 3 ? k - f.centre[2] : 0.0};
              const double g = f.strength * std::exp(-(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) / (f.radius * f.radius));
              const double up[3] = {f.up[0], f.up[1], L.dim == 3 ? f.up[2] : 1.0};
              const double cr[3] = {up[1] * r[2] - up[2] * r[1], up[2] * r[0] - up[0] * r[2], up[0] * r[1] - up[1] * r[0]};
              const std::size_t n = L.index(i, j, k);
              for (int c = 0; c < L.dim; ++c) u[c][n] += dt * g * cr[c];
            }
        break;
      }
    }
  }
  // Jets: the velocity inside a source region is set, every step the source is active.
  for (const ScalarSpec& sc : scene_.scalars)
    for (const Source& src : sc.sources)
      if (src.jet && active_at(src, st.t))
        for_region(L, src, [&](std::size_t n, double) {
          for (int c = 0; c < L.dim; ++c) u[c][n] = src.velocity[c];
        });
  enforce_walls(L, u, scene_.no_slip);
}

void Simulator::scalar_sources(const State& st, double dt, std::vector<Field>& src) const {
  src.resize(st.s.size());
  for (std::size_t i = 0; i < st.s.size(); ++i) parallel_copy(st.s[i], src[i]);
  for (std::size_t i = 0; i < scene_.scalars.size(); ++i)
    for (const Source& s : scene_.scalars[i].sources)
      if (active_at(s, st.t) && s.rate != 0.0)
        for_region(layout_, s, [&](std::size_t n, double w) { src[i][n] += dt * s.rate * w; });
}

void Simulator::finish_scalars(const std::vector<Field>& before, std::vector<Field>& s, double dt) const {
  const Layout& L = layout_;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const ScalarSpec& sc = scene_.scalars[i];
    if (options_.mass_correct) {
      const double b = weighted_sum(L, before[i]), a = weighted_sum(L, s[i]);
      if (a != 0.0 && b != 0.0) {
        const double f = b / a;  // the same product per value as before, on any team
        double* v = s[i].data();
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
        for (std::size_t n = 0; n < L.count(); ++n) v[n] *= f;
      }
    }
    if (sc.kappa > 0.0) diffuser(sc.kappa * dt)->scalar(s[i]);
    if (sc.alpha > 0.0) {
      const double f = 1.0 / (1.0 + sc.alpha * dt);
      double* v = s[i].data();
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
      for (std::size_t n = 0; n < L.count(); ++n) v[n] *= f;
    }
  }
}

const Diffuser* Simulator::diffuser(double c) const {
  for (const auto& d : diffusers_)
    if (d->coefficient() == c) return d.get();
  diffusers_.push_back(std::make_unique<Diffuser>(
      layout_, c, options_.projection.solver == PoissonSolver::fft ? Transform::fftw : Transform::dense,
      scene_.no_slip));
  return diffusers_.back().get();
}

StepStats Simulator::step(State& st, double dt) const {
  const Layout& L = layout_;
  StepStats stats;
  auto t0 = Clock::now();
  Velocity w = std::move(spare_u_[0]);
  for (int c = 0; c < 3; ++c) parallel_copy(st.u[c], w[c]);
  add_forces(st, dt, w);
  stats.ms_force = ms_since(t0);

  t0 = Clock::now();
  std::vector<Field> sources = std::move(spare_s_[0]);
  scalar_sources(st, dt, sources);
  // The advected scalars: advect() writes every node.
  std::vector<Field> s_next = std::move(spare_s_[1]);
  s_next.resize(sources.size());
  for (Field& f : s_next) ensure_size(f, L.count());
  stats.ms_scalars = ms_since(t0);

  auto diffuse = [&](Velocity& v) {
    const auto t = Clock::now();
    if (scene_.viscosity > 0.0) {
      const Diffuser* d = diffuser(scene_.viscosity * dt);
      // The components' solves stage by stage, each stage's pieces (lines, rows, modes)
      // shared by the whole team (3 component tasks would use at most 3 threads).
      d->velocity(v);
      enforce_walls(L, v, scene_.no_slip);
    }
    stats.ms_diffuse += ms_since(t);
  };
  // One RK4 back-trace per node through v serves the velocity and, when `with_scalars`,
  // every scalar: they all take their value at the same departure point.
  auto advect_self = [&](Velocity& v, bool with_scalars) {
    const auto t = Clock::now();
    Velocity out = std::move(spare_u_[1]);  // advect() writes every node
    std::vector<const Field*> in;
    std::vector<Field*> to;
    for (int c = 0; c < L.dim; ++c) {
      ensure_size(out[c], L.count());
      in.push_back(&v[c]);
      to.push_back(&out[c]);
    }
    if (with_scalars)
      for (std::size_t i = 0; i < sources.size(); ++i) {
        in.push_back(&sources[i]);
        to.push_back(&s_next[i]);
      }
    advect(L, v, dt, scene_.substeps, in, to);
    for (int c = 0; c < L.dim; ++c) v[c].swap(out[c]);
    spare_u_[1] = std::move(out);  // v's old buffers, for the next step's advection
    enforce_walls(L, v, scene_.no_slip);
    stats.ms_advect += ms_since(t);
  };
  auto project = [&](Velocity& v) {
    const auto t = Clock::now();
    stats.projection = projector_->project(v);
    stats.ms_project += ms_since(t);
  };

  if (options_.stam03) {
    // Stam's order; the scalars are traced through the velocity of level n.
    t0 = Clock::now();
    std::vector<const Field*> in;
    std::vector<Field*> to;
    for (std::size_t i = 0; i < sources.size(); ++i) {
      in.push_back(&sources[i]);
      to.push_back(&s_next[i]);
    }
    if (!in.empty()) advect(L, st.u, dt, scene_.substeps, in, to);
    stats.ms_scalars += ms_since(t0);
    diffuse(w);
    project(w);
    advect_self(w, false);
    project(w);
  } else {
    // Force -> advect (velocity and scalars along the same characteristics of w1 =
    // u^n + dt f(s^n), which depends on level n only) -> diffuse -> project.
    advect_self(w, true);
    diffuse(w);
    project(w);
  }
  t0 = Clock::now();
  finish_scalars(sources, s_next, dt);
  stats.ms_scalars += ms_since(t0);
  std::swap(st.u, w);
  std::swap(st.s, s_next);
  spare_u_[0] = std::move(w);  // the old state's buffers, for the next step's copy
  spare_s_[0] = std::move(sources);
  spare_s_[1] = std::move(s_next);
  st.t += dt;
  st.step += 1;
  check_finite(L, st);
  return stats;
}

void blend(const State& x, const State& y, double a, State& out) {
  auto mix = [a](const Field& p, const Field& q, Field& r) {
    if (r.size() != p.size()) r.resize(p.size());
    const double *pp = p.data(), *qq = q.data();
    double* rr = r.data();
#pragma omp parallel for schedule(static) if (r.size() >= kParallelNodes)
    for (std::size_t n = 0; n < r.size(); ++n) rr[n] = (1.0 - a) * pp[n] + a * qq[n];
  };
  for (int c = 0; c < 3; ++c) mix(x.u[c], y.u[c], out.u[c]);
  out.s.resize(x.s.size());
  for (std::size_t i = 0; i < x.s.size(); ++i) mix(x.s[i], y.s[i], out.s[i]);
  out.t = (1.0 - a) * x.t + a * y.t;
  out.step = x.step;
}

State blend(const State& x, const State& y, double a) {
  State out;
  blend(x, y, a, out);
  return out;
}

double max_speed(const Layout& L, const Velocity& u) {
  double m = 0.0;  // a maximum: the same for any split of the nodes
#pragma omp parallel for schedule(static) reduction(max : m) if (L.count() >= kParallelNodes)
  for (std::size_t n = 0; n < L.count(); ++n) {
    double s = 0.0;
    for (int c = 0; c < L.dim; ++c) s += u[c][n] * u[c][n];
    m = std::max(m, s);
  }
  return std::sqrt(m);
}

}  // namespace fest::fluidsim

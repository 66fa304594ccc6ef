// lmfsim chain benchmark (docs/lmfsim.md §7) with ODE 0.16 (Debian libode-dev) on the same chains
// in the same run: N boxes L x 0.02 x 0.02 m (L = 1/N m, 1 kg in all), ball joints, the
// first to the world, horizontal at rest, gravity 9.81; h = 1e-3 over 0.5 s.
// Prints one JSON line per case: steps/s, max joint separation, energy (exact: E = 0).
//
//   build/bin/bench_lmfsim [--quick]      (--quick: N = 10 and 100 only)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lmfsim/simulate.hpp"

#ifdef FEST_HAVE_ODE
#include <ode/ode.h>
#endif

using namespace fest::lmfsim;
using nlohmann::json;

namespace {

constexpr double kG = 9.81, kT = 0.5;

Scene chain(int n, double h, SolverKind solver) {
  Scene s;
  const double L = 1.0 / n, m = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    Body b;
    b.name = "l" + std::to_string(i);
    b.mass = m;
    b.pos = Vec3((i + 0.5) * L, 0, 0);
    b.shape.kind = Shape::Kind::box;
    b.shape.dims = Vec3(L, 0.02, 0.02);
    b.inertia = shape_inertia(b.shape, m);
    s.bodies.push_back(b);
    Constraint c;
    c.name = "j" + std::to_string(i);
    c.type = ConstraintType::ball;
    c.a = i - 1;
    c.pa = i == 0 ? Vec3::Zero() : Vec3(L / 2, 0, 0);
    c.b = i;
    c.pb = Vec3(-L / 2, 0, 0);
    s.constraints.push_back(c);
  }
  s.sim.t_end = kT;
  s.sim.dt = h;
  s.sim.every = 100;
  s.sim.solver = solver;
  s.sim.max_violation = 1;
  return s;
}

struct Figures {
  double steps_per_s = 0, max_sep = 0, max_abs_E = 0, E_end = 0, wall_per_sim_s = 0;
  // Steps per second of process CPU time: on a shared, loaded machine wall time also
  // counts the time other processes hold the core; CPU time does not.
  double cpu_steps_per_s = 0;
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Best of `repeats` timed runs, plus one probed run for separation and energy.
Figures run_lmfsim(int n, double h, SolverKind solver, int repeats, double t_end = kT, bool accuracy = true) {
  Figures f;
  double best = 1e300, best_cpu = 1e300;
  for (int r = 0; r < repeats; ++r) {
    Scene s = chain(n, h, solver);
    s.sim.t_end = t_end;
    System sys(s);
    const double c0 = cpu_seconds();
    const RunSummary sum = simulate(sys, [](int, double, const Eigen::VectorXd&) {});
    best_cpu = std::min(best_cpu, (cpu_seconds() - c0) / static_cast<double>(sum.steps));
    best = std::min(best, sum.wall_s / static_cast<double>(sum.steps));
  }
  f.steps_per_s = 1 / best;
  f.cpu_steps_per_s = 1 / best_cpu;
  f.wall_per_sim_s = best / h;
  if (!accuracy) return f;
  Scene s = chain(n, h, solver);
  s.sim.every = 1;
  s.sim.t_end = t_end;
  System sys(s);
  const double L = 1.0 / n;
  simulate(sys, [&](int, double, const Eigen::VectorXd& st) {
    Vec3 prev = Vec3::Zero();
    for (int i = 0; i < n; ++i) {
      const BodyKin k = sys.kinematics(i, st);
      f.max_sep = std::max(f.max_sep, (k.p + k.R * Vec3(-L / 2, 0, 0) - prev).norm());
      prev = k.p + k.R * Vec3(L / 2, 0, 0);
    }
    f.E_end = sys.energy(st).E();
    f.max_abs_E = std::max(f.max_abs_E, std::abs(f.E_end));
  });
  return f;
}

#ifdef FEST_HAVE_ODE
Figures run_ode(int n, bool quick, int repeats) {
  Figures f;
  double best = 1e300, best_cpu = 1e300;
  for (int r = 0; r < repeats; ++r) {
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -kG);
    dWorldSetERP(w, 0.2);
    dWorldSetCFM(w, 1e-10);
    dWorldSetQuickStepNumIterations(w, 20);
    const double L = 1.0 / n, m = 1.0 / n;
    std::vector<dBodyID> bodies;
    std::vector<dJointID> joints;
    for (int i = 0; i < n; ++i) {
      dBodyID b = dBodyCreate(w);
      dMass mass;
      dMassSetBoxTotal(&mass, m, L, 0.02, 0.02);
      dBodySetMass(b, &mass);
      dBodySetPosition(b, (i + 0.5) * L, 0, 0);
      dJointID j = dJointCreateBall(w, nullptr);
      dJointAttach(j, i == 0 ? nullptr : bodies.back(), b);
      dJointSetBallAnchor(j, i * L, 0, 0);
      bodies.push_back(b);
      joints.push_back(j);
    }
    const int steps = static_cast<int>(std::lround(kT / 1e-3));
    const bool probe = r == 0;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    double probe_time = 0, probe_cpu = 0;
    for (int k = 0; k < steps; ++k) {
      if (quick) dWorldQuickStep(w, 1e-3);
      else dWorldStep(w, 1e-3);
      if (!probe) continue;
      const auto p0 = std::chrono::steady_clock::now();
      const double pc0 = cpu_seconds();
      double E = 0;
      for (int i = 0; i < n; ++i) {
        dVector3 a1, a2;
        dJointGetBallAnchor(joints[static_cast<std::size_t>(i)], a1);
        dJointGetBallAnchor2(joints[static_cast<std::size_t>(i)], a2);
        f.max_sep = std::max(f.max_sep, std::sqrt((a1[0] - a2[0]) * (a1[0] - a2[0]) + (a1[1] - a2[1]) * (a1[1] - a2[1]) +
                                                  (a1[2] - a2[2]) * (a1[2] - a2[2])));
        const dReal* p = dBodyGetPosition(bodies[static_cast<std::size_t>(i)]);
        const dReal* v = dBodyGetLinearVel(bodies[static_cast<std::size_t>(i)]);
        const dReal* om = dBodyGetAngularVel(bodies[static_cast<std::size_t>(i)]);
        const dReal* R = dBodyGetRotation(bodies[static_cast<std::size_t>(i)]);
        Mat3 Rm;
        Rm << R[0], R[1], R[2], R[4], R[5], R[6], R[8], R[9], R[10];
        Shape sh;
        sh.kind = Shape::Kind::box;
        sh.dims = Vec3(L, 0.02, 0.02);
        const Mat3 Iw = Rm * shape_inertia(sh, m) * Rm.transpose();
        const Vec3 wv(om[0], om[1], om[2]);
        E += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * wv.dot(Iw * wv) + m * kG * p[2];
      }
      f.E_end = E;
      f.max_abs_E = std::max(f.max_abs_E, std::abs(E));
      probe_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count();
      probe_cpu += cpu_seconds() - pc0;
    }
    best_cpu = std::min(best_cpu, (cpu_seconds() - c0 - probe_cpu) / steps);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() - probe_time;
    best = std::min(best, wall / steps);
    dWorldDestroy(w);
  }
  f.steps_per_s = 1 / best;
  f.cpu_steps_per_s = 1 / best_cpu;
  f.wall_per_sim_s = best / 1e-3;
  return f;
}
#endif

void print(json j) { std::printf("%s\n", j.dump().c_str()); std::fflush(stdout); }

json figures(const Figures& f) {
  return {{"steps_per_s", f.steps_per_s}, {"cpu_steps_per_s", f.cpu_steps_per_s}, {"max_joint_separation_m", f.max_sep}, {"max_abs_E_J", f.max_abs_E},
          {"E_end_J", f.E_end}};
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::vector<int> sizes = quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
#ifdef FEST_HAVE_ODE
  dInitODE2(0);
#endif
  for (int n : sizes) {
    const Figures lm = run_lmfsim(n, 1e-3, SolverKind::baraff, 3);
    json j = {{"bench", "lmfsim_chain"}, {"N", n}, {"h", 1e-3}, {"t", kT}, {"engine", "lmfsim baraff rk4 baumgarte 10"}};
    j.update(figures(lm));
    print(j);
#ifdef FEST_HAVE_ODE
    for (bool q : {false, true}) {
      if (!q && n > 100) {  // dWorldStep is O(m^3): minutes per step at N = 1000
        print({{"bench", "lmfsim_chain"}, {"N", n}, {"engine", "ode dWorldStep"}, {"note", "skipped: O(m^3) big-matrix LCP"}});
        continue;
      }
      const Figures od = run_ode(n, q, 3);
      json o = {{"bench", "lmfsim_chain"}, {"N", n}, {"h", 1e-3}, {"t", kT},
                {"engine", q ? "ode dWorldQuickStep 20 it, ERP 0.2, CFM 1e-10" : "ode dWorldStep, ERP 0.2, CFM 1e-10"}};
      o.update(figures(od));
      print(o);
    }
#else
    print({{"bench", "lmfsim_chain"}, {"N", n}, {"engine", "ode"}, {"note", "ODE (libode-dev) not found at build time"}});
#endif
    // Accuracy at cost: the largest h with separation <= 1e-5 m and |E| <= 1e-4 J.
    json acc = {{"bench", "lmfsim_accuracy_at_cost"}, {"N", n}};
    bool found = false;
    for (double h : {1e-3, 5e-4, 2.5e-4, 1.25e-4}) {
      const Figures f = run_lmfsim(n, h, SolverKind::baraff, 1);
      if (f.max_sep <= 1e-5 && f.max_abs_E <= 1e-4) {
        acc.update({{"h", h}, {"wall_s_per_simulated_s", f.wall_per_sim_s},
                    {"cpu_s_per_simulated_s", 1 / (f.cpu_steps_per_s * h)}, {"max_joint_separation_m", f.max_sep},
                    {"max_abs_E_J", f.max_abs_E}});
        found = true;
        break;
      }
      acc["rejected_h_" + std::to_string(h)] = figures(f);
    }
    if (!found) acc["note"] = "needs h < 1.25e-4";
    print(acc);
  }
  // Scaling: time per step against N (log-log slope by least squares).
  std::vector<double> lx, ly, ly_cpu;
  json pts = json::array();
  for (int n : quick ? std::vector<int>{10, 30, 100} : std::vector<int>{10, 30, 100, 300, 1000}) {
    const Figures f = run_lmfsim(n, 1e-3, SolverKind::baraff, 3, 0.1, false);
    lx.push_back(std::log(n));
    ly.push_back(std::log(1 / f.steps_per_s));
    ly_cpu.push_back(std::log(1 / f.cpu_steps_per_s));
    pts.push_back({{"N", n}, {"us_per_step", 1e6 / f.steps_per_s}, {"cpu_us_per_step", 1e6 / f.cpu_steps_per_s}});
  }
  // Least-squares slope of y against log N.
  const auto slope = [&lx](const std::vector<double>& y) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) mx += lx[i], my += y[i];
    mx /= static_cast<double>(lx.size());
    my /= static_cast<double>(lx.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) sxy += (lx[i] - mx) * (y[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
    return sxy / sxx;
  };
  print({{"bench", "lmfsim_scaling"}, {"solver", "baraff"}, {"points", pts}, {"loglog_slope", slope(ly)},
         {"cpu_loglog_slope", slope(ly_cpu)}, {"target", "<= 1.15"}});
  const Figures dense = run_lmfsim(100, 1e-3, SolverKind::dense, 1, 0.1, false);
  print({{"bench", "lmfsim_dense"}, {"N", 100}, {"steps_per_s", dense.steps_per_s}, {"target", ">= 50"}});
#ifdef FEST_HAVE_ODE
  dCloseODE();
#endif
  return 0;
}

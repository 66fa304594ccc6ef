// lmfsim run: scene in, trajectory CSV (and diagnostics, forces, a report) out.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "core/resources.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/tool_main.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/simulate.hpp"
#include "trajectory_csv.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

namespace {

const char* integrator_name(Integrator i) {
  switch (i) {
    case Integrator::euler: return "euler";
    case Integrator::symplectic: return "symplectic";
    case Integrator::rk4: return "rk4";
    case Integrator::rk45: return "rk45";
  }
  return "?";
}

TrajectoryRow body_row(const System& sys, int b, long frame, double t, const Eigen::VectorXd& s) {
  const BodyKin k = sys.kinematics(b, s);
  TrajectoryRow r;
  r.frame = frame;
  r.t = t;
  r.body = sys.scene().bodies[static_cast<std::size_t>(b)].name;
  r.p = k.p;
  r.q = sys.orientation(b, s);
  r.v = k.v;
  r.w = k.w;
  return r;
}

// simulate(), with the limit on |C| named by the flag that sets it.
RunSummary simulate_run(System& sys, const FrameCallback& on_frame) {
  try {
    return simulate(sys, on_frame);
  } catch (const ViolationLimitExceeded& e) {
    throw fest::runtime_failure("constraint violation {:.3g} exceeds the limit {:.3g} (t={:.6g}, see --max-violation)",
                                e.violation, e.limit, e.t);
  }
}

}  // namespace

int cmd_run(const RunOptions& opt) {
  // Steps depend on the previous ones and Baraff's elimination is a sequential sweep:
  // there is no parallel part to give the threads (lmfsim(1), BUGS).
  if (opt.threads > 1)
    fest::warn("lmfsim", fmt::format("--threads {}: the integrator is sequential and runs one thread", opt.threads));
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  Scene scene = load_scene(scene_bytes);
  opt.sim.apply(scene.sim);
  System sys(std::move(scene));
  const SimSettings& sim = sys.settings();
  const auto& bodies = sys.scene().bodies;
  const int nb = static_cast<int>(bodies.size());
  if (!opt.stream) {
    // Nothing is written unless everything worked, so the rows wait in memory: about
    // 256 bytes a body a frame (13 numbers of 9 digits, the frame, time and name).
    const double frames = std::floor(sim.t_end / sim.dt / sim.every) + 1;
    fest::check_fits_in_memory(
        frames * std::max(nb, 1) * 256.0,
        fmt::format("a trajectory of {:.0f} frames of {} bodies held until the run ends (--stream writes it as it comes)",
                    frames, nb));
  }

  if (sim.formulation == Formulation::penalty) {
    // Stiffness warning of docs/lmfsim.md §5: h w0 sqrt(kappa max diag(J M^-1 J^T)) > 0.5.
    const Eigen::VectorXd s0 = sys.initial_state();
    Eigen::VectorXd ds;
    sys.derivative(0, s0, ds);
    double mass_min = 1e300;
    for (const Body& b : bodies) if (!b.fixed) mass_min = std::min(mass_min, b.mass);
    const double stiff = sim.dt * sim.omega0 * std::sqrt(sim.kappa / mass_min);
    if (stiff > 0.5)
      fest::warn("lmfsim", fmt::format("penalty springs are stiff for this step: h*omega0*sqrt(kappa/m) = {:.3g} > 0.5", stiff));
  }

  std::string out;
  auto emit = [&](bool final_flush) {
    if (opt.stream && (final_flush || out.size() > (1u << 16))) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      std::fflush(stdout);
      out.clear();
    }
  };
  if (opt.wide) {
    out += "t";
    for (const Body& b : bodies)
      for (const char* c : {"px", "py", "pz", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"})
        out += fmt::format(",{}.{}", b.name, c);
    out += "\n";
  } else {
    out += trajectory_header();
  }
  std::string diag = "frame,t,T,U,E,drift_rel,C_max,Cdot_max,Cv_max,rows,rank_def,solve_us\n";
  std::string forces = "frame,t,item,name,row,lambda,fx,fy,fz,tx,ty,tz\n";
  const Eigen::VectorXd s0 = sys.initial_state();
  const double E0 = sys.energy(s0).E(), Escale = sys.energy_scale();
  double max_drift = 0, max_Cdot = 0, max_C = 0;
  Eigen::VectorXd ds;
  const bool need_eval = !opt.diag.empty() || !opt.forces.empty() || !opt.report.empty();

  // --progress: the simulated time of t_end, in thousandths.
  fest::Progress bar("lmfsim run", 1000, fest::progress_wanted(opt.progress));
  auto on_frame = [&](int frame, double t, const Eigen::VectorXd& s) {
    if (sim.t_end > 0) bar.set(static_cast<std::uint64_t>(1000 * std::clamp(t / sim.t_end, 0.0, 1.0)));
    const Energy en = sys.energy(s);
    const double drift = std::abs(en.E() - E0) / Escale;
    max_drift = std::max(max_drift, drift);
    if (need_eval) {
      sys.derivative(t, s, ds);
      const EvalInfo& info = sys.info();
      max_C = std::max(max_C, info.C_max);
      max_Cdot = std::max(max_Cdot, info.Cdot_max);
      if (!opt.diag.empty())
        diag += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{},{:.3f}\n", frame, t, en.T,
                            en.U, en.E(), drift, info.C_max, info.Cdot_max, info.Cv_max, info.rows,
                            info.rank_deficiency, info.solve_us);
      if (!opt.forces.empty()) {
        const auto& cons = sys.scene().constraints;
        for (std::size_t j = 0; j < cons.size(); ++j) {
          const Vecx& lam = sys.lambda()[j];
          for (Eigen::Index r = 0; r < lam.size(); ++r)
            forces += fmt::format("{},{:.9g},constraint,{},{},{:.9g},,,,,,\n", frame, t, cons[j].name, r, lam[r]);
        }
        const std::vector<Vec6> w = sys.constraint_wrenches(t, s);
        for (int b = 0; b < nb; ++b) {
          const Vec6& f = w[static_cast<std::size_t>(b)];
          forces += fmt::format("{},{:.9g},body,{},,,{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", frame, t,
                                bodies[static_cast<std::size_t>(b)].name, f[0], f[1], f[2], f[3], f[4], f[5]);
        }
      }
    }
    if (opt.wide) {
      out += fmt::format("{:.9g}", t);
      for (int b = 0; b < nb; ++b) {
        const TrajectoryRow r = body_row(sys, b, frame, t, s);
        out += fmt::format(",{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", r.p.x(),
                           r.p.y(), r.p.z(), r.q.w(), r.q.x(), r.q.y(), r.q.z(), r.v.x(), r.v.y(), r.v.z(), r.w.x(),
                           r.w.y(), r.w.z());
      }
      out += "\n";
    } else {
      for (int b = 0; b < nb; ++b) append_row(out, body_row(sys, b, frame, t, s));
    }
    emit(false);
  };

  RunSummary sum;
  try {
    sum = simulate_run(sys, on_frame);
    bar.finish();
  } catch (const fest::Error& e) {
    if (opt.stream) {
      emit(true);
      std::fprintf(stdout, "# ERROR %s\n", e.what());
      std::fflush(stdout);
    }
    throw;
  }
  max_C = std::max(max_C, sum.max_C);
  // Side files first, then standard output: nothing is written unless everything worked.
  if (!opt.diag.empty()) fest::write_output(opt.diag, diag);
  if (!opt.forces.empty()) fest::write_output(opt.forces, forces);
  if (!opt.report.empty()) {
    nlohmann::json rep = {{"steps", sum.steps},
                          {"evals", sum.evals},
                          {"wall_s", sum.wall_s},
                          {"steps_per_s", sum.wall_s > 0 ? static_cast<double>(sum.steps) / sum.wall_s : 0.0},
                          {"max_C", max_C},
                          {"max_Cdot", max_Cdot},
                          {"energy_drift_rel", max_drift},
                          {"conservative", sys.conservative()},
                          {"E_scale", Escale},
                          {"solver", sim.solver == SolverKind::dense ? "dense" : "baraff"},
                          {"formulation", sim.formulation == Formulation::lmf ? "lmf" : "penalty"},
                          {"integrator", integrator_name(sim.integrator)}};
    fest::write_output(opt.report, fest::formats::write_json(rep));
  }
  if (opt.stream) emit(true);
  else fest::write_output("-", out);
  return 0;
}

}  // namespace fest::lmfsim_tool

// lmfsim run / check / assemble: scene in, trajectory CSV (and diagnostics) out.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include <Eigen/SVD>
#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/scene_json.hpp"
#include "lmfsim/simulate.hpp"
#include "lmfsim/solver.hpp"
#include "trajectory_csv.hpp"

namespace lmfsim_tool {

using namespace fest::lmfsim;

void SimOverrides::apply(SimSettings& sim) const {
  if (dt) sim.dt = *dt;
  if (t_end) sim.t_end = *t_end;
  if (every) sim.every = *every;
  if (alpha) sim.alpha = *alpha;
  if (beta) sim.beta = *beta;
  if (kappa) sim.kappa = *kappa;
  if (omega0) sim.omega0 = *omega0;
  if (zeta) sim.zeta = *zeta;
  if (svd_tol) sim.svd_tol = *svd_tol;
  if (max_violation) sim.max_violation = *max_violation;
  if (rtol) sim.rtol = *rtol;
  if (atol) sim.atol = *atol;
  if (integrator == "euler") sim.integrator = Integrator::euler;
  if (integrator == "symplectic") sim.integrator = Integrator::symplectic;
  if (integrator == "rk4") sim.integrator = Integrator::rk4;
  if (integrator == "rk45") sim.integrator = Integrator::rk45;
  if (solver == "baraff") sim.solver = SolverKind::baraff;
  if (solver == "dense") sim.solver = SolverKind::dense;
  if (formulation == "lmf") sim.formulation = Formulation::lmf;
  if (formulation == "penalty") sim.formulation = Formulation::penalty;
  if (stab == "none") sim.stab = Stabilization::none;
  if (stab == "baumgarte") sim.stab = Stabilization::baumgarte;
  if (stab == "force") sim.stab = Stabilization::force;
  if (stab == "project") sim.stab = Stabilization::project;
  if (!(sim.dt > 0) || !std::isfinite(sim.dt)) throw fest::usage_error("--dt must be positive (got {})", sim.dt);
  if (!(sim.t_end >= 0)) throw fest::usage_error("--t-end must be >= 0 (got {})", sim.t_end);
  if (sim.every < 1) throw fest::usage_error("--every must be >= 1 (got {})", sim.every);
}

Scene load_scene(const std::string& bytes) {
  if (bytes.find_first_not_of(" \t\r\n") == std::string::npos) throw fest::bad_input("empty scene on standard input");
  const nlohmann::json doc = fest::formats::read_json(bytes);
  auto loader = [](const std::string& path, std::vector<Vec3>& v, std::vector<std::array<int, 3>>& t) {
    const fest::formats::Input in = fest::formats::load_input(path);
    const fest::Mesh mesh = fest::formats::parse(in, fest::formats::read_mesh);
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      v.emplace_back(p[0], p[1], p[2]);
    }
    for (auto fh : mesh.faces()) {
      std::vector<int> idx;
      for (auto fv : mesh.fv_range(fh)) idx.push_back(fv.idx());
      if (idx.size() < 3) continue;
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) t.push_back({idx[0], idx[k], idx[k + 1]});  // fan
    }
    if (mesh.n_vertices() == 0) throw fest::bad_input("mesh has no vertices ({})", path);
    for (auto eh : mesh.edges())
      if (mesh.is_boundary(eh)) throw fest::bad_input("mesh is not closed ({})", path);
  };
  return scene_from_json(doc, loader);
}

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

}  // namespace

int cmd_run(const RunOptions& opt) {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  Scene scene = load_scene(scene_bytes);
  opt.sim.apply(scene.sim);
  System sys(std::move(scene));
  const SimSettings& sim = sys.settings();
  const auto& bodies = sys.scene().bodies;
  const int nb = static_cast<int>(bodies.size());

  if (sim.formulation == Formulation::penalty) {
    // Stiffness warning of spec §2.5: h w0 sqrt(kappa max diag(J M^-1 J^T)) > 0.5.
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

  auto on_frame = [&](int frame, double t, const Eigen::VectorXd& s) {
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
    sum = simulate(sys, on_frame);
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

int cmd_check(const SimOverrides& over) {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  Scene scene = load_scene(scene_bytes);
  over.apply(scene.sim);
  System sys(std::move(scene));
  const Scene& sc = sys.scene();
  const Eigen::VectorXd s0 = sys.initial_state();
  Eigen::VectorXd C;
  const Eigen::MatrixXd J = sys.jacobian(0, s0, &C);
  int rank = 0;
  if (J.rows() > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
    const auto& sv = svd.singularValues();
    for (Eigen::Index i = 0; i < sv.size(); ++i)
      if (sv[i] > sc.sim.svd_tol * sv[0]) ++rank;
  }
  // Topology: primary (spanning forest) versus auxiliary rows, components.
  std::vector<SolveConstraint> cons;
  std::vector<int> moving(sc.bodies.size(), -1);
  int nm = 0;
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    if (!sc.bodies[i].fixed) moving[i] = nm++;
  std::vector<const Constraint*> active;
  for (const Constraint& c : sc.constraints) {
    if (!c.active) continue;
    SolveConstraint s;
    s.a = c.a < 0 ? -1 : moving[static_cast<std::size_t>(c.a)];
    s.b = c.b < 0 ? -1 : moving[static_cast<std::size_t>(c.b)];
    s.c.setZero(constraint_rows(c.type));
    cons.push_back(s);
    active.push_back(&c);
  }
  const std::vector<bool> primary = primary_constraints(nm, cons);
  int prim_rows = 0, aux_rows = 0;
  nlohmann::json aux = nlohmann::json::array();
  for (std::size_t j = 0; j < cons.size(); ++j) {
    if (primary[j]) prim_rows += cons[j].rows();
    else {
      aux_rows += cons[j].rows();
      aux.push_back(active[j]->name);
    }
  }
  // Components of the body graph without the ground (a free body is one).
  std::vector<int> comp(static_cast<std::size_t>(nm));
  for (int i = 0; i < nm; ++i) comp[static_cast<std::size_t>(i)] = i;
  std::function<int(int)> find = [&](int i) { return comp[static_cast<std::size_t>(i)] == i ? i : comp[static_cast<std::size_t>(i)] = find(comp[static_cast<std::size_t>(i)]); };
  for (const auto& s : cons)
    if (s.a >= 0 && s.b >= 0) comp[static_cast<std::size_t>(find(s.a))] = find(s.b);
  std::set<int> roots;
  for (int i = 0; i < nm; ++i) roots.insert(find(i));
  const double h = sc.sim.dt, beta = sc.sim.beta;
  const bool euler = sc.sim.integrator == Integrator::euler || sc.sim.integrator == Integrator::symplectic;
  const double limit = euler ? 0.05 : 0.2;
  nlohmann::json rep = {{"bodies", sc.bodies.size()},
                        {"moving_bodies", nm},
                        {"dof_unconstrained", sys.dof_total()},
                        {"constraints", sc.constraints.size()},
                        {"active_rows", J.rows()},
                        {"components", roots.size()},
                        {"primary_rows", prim_rows},
                        {"auxiliary_rows", aux_rows},
                        {"auxiliary_constraints", aux},
                        {"rank_J", rank},
                        {"rank_deficiency", static_cast<int>(J.rows()) - rank},
                        {"dof", sys.dof_total() - rank},
                        {"initial_C_max", C.size() ? C.cwiseAbs().maxCoeff() : 0.0},
                        {"length_scale", sys.length_scale()},
                        {"beta_h", beta * h},
                        {"beta_h_limit", limit},
                        {"stabilisation_ok", sc.sim.stab != Stabilization::baumgarte || beta * h <= limit}};
  fest::write_output("-", fest::formats::write_json(rep));
  return 0;
}

int cmd_assemble() {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  nlohmann::json doc = fest::formats::read_json(scene_bytes);
  Scene scene = load_scene(scene_bytes);
  scene.sim.stab = Stabilization::project;
  System sys(std::move(scene));
  Eigen::VectorXd s = sys.initial_state();
  sys.project(0, s);
  const double res = sys.max_violation(0, s);
  if (!(res <= 1e-9 * sys.length_scale()))
    throw fest::runtime_failure("cannot assemble: |C| = {:.3g} after projection (conflicting constraints?)", res);
  const auto& bodies = sys.scene().bodies;
  std::vector<Vec3> pos, vel, omega;
  std::vector<Quat> quat;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyKin k = sys.kinematics(static_cast<int>(b), s);
    pos.push_back(k.p);
    vel.push_back(k.v);
    omega.push_back(k.w);
    quat.push_back(sys.orientation(static_cast<int>(b), s));
  }
  write_state(doc, sys.scene(), pos, quat, vel, omega);
  fest::write_output("-", fest::formats::write_json(doc));
  return 0;
}

}  // namespace lmfsim_tool

// Forces, stabilisation and the derivative evaluation of docs/lmfsim.md §1-§4, §6.
#include <Eigen/LU>

#include "lmfsim/system.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/stopwatch.hpp"

namespace fest::lmfsim {
namespace {

Vec3 world_point(const BodyKin& k, const Vec3& r) { return k.p + k.R * r; }

}  // namespace

System::System(Scene scene) : scene_(std::move(scene)) {
  validate_scene(scene_);
  const std::size_t nb = scene_.bodies.size();
  moving_.assign(nb, -1);
  for (std::size_t i = 0; i < nb; ++i) {
    const Body& b = scene_.bodies[i];
    if (b.fixed) continue;
    moving_[i] = static_cast<int>(moving_body_.size());
    moving_body_.push_back(static_cast<int>(i));
    offset_.push_back(n_state_);
    const bool rigid = b.kind == BodyKind::rigid;
    const int pos = rigid ? 7 : 3, vel = rigid ? 6 : 3;
    n_state_ += pos + vel;
    n_dof_ += vel;
    for (int k = 0; k < pos; ++k) vel_mask_.push_back(false);
    for (int k = 0; k < vel; ++k) vel_mask_.push_back(true);
  }
  pid_offset_.assign(scene_.forces.size(), -1);
  for (std::size_t f = 0; f < scene_.forces.size(); ++f) {
    if (scene_.forces[f].type != ForceType::pid) continue;
    pid_offset_[f] = n_state_;
    n_state_ += 3;
    for (int k = 0; k < 3; ++k) vel_mask_.push_back(false);
  }
  for (const Event& e : scene_.events) check_event(e);

  // Length scale: diagonal of the bounding box of the initial COMs and anchors, >= 1 m.
  if (scene_.length_scale > 0) {
    length_scale_ = scene_.length_scale;
  } else {
    const Eigen::VectorXd s0 = initial_state();
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < nb; ++i) box.extend(scene_.bodies[i].pos);
    for (const Constraint& c : scene_.constraints) {
      box.extend(world_point(kinematics(c.a, s0), c.pa));
      box.extend(world_point(kinematics(c.b, s0), c.pb));
    }
    length_scale_ = std::max(1.0, box.isEmpty() ? 0.0 : box.diagonal().norm());
  }
  if (scene_.sim.max_violation < 0) scene_.sim.max_violation = 0.01 * length_scale_;
  double mass = 0;
  for (int b : moving_body_) mass += scene_.bodies[static_cast<std::size_t>(b)].mass;
  energy_scale_ = mass * scene_.gravity.norm() * length_scale_ + energy(initial_state()).T;
  if (!(energy_scale_ > 0)) energy_scale_ = 1;

  solver_ = scene_.sim.solver == SolverKind::dense ? make_dense_solver(scene_.sim.svd_tol)
                                                   : make_baraff_solver(scene_.sim.svd_tol);
  for (const Body& b : scene_.bodies) inertia_inv_.push_back(b.kind == BodyKind::rigid ? Mat3(b.inertia.inverse()) : Mat3::Zero());
  kin_.resize(nb);
  bodies_.resize(moving_body_.size());
  lambda_.resize(scene_.constraints.size());
  collect_active();
}

Eigen::VectorXd System::initial_state() const {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(n_state_);
  for (std::size_t m = 0; m < moving_body_.size(); ++m) {
    const Body& b = scene_.bodies[static_cast<std::size_t>(moving_body_[m])];
    const int o = offset_[m];
    s.segment<3>(o) = b.pos;
    if (b.kind == BodyKind::rigid) {
      s.segment<4>(o + 3) << b.quat.w(), b.quat.x(), b.quat.y(), b.quat.z();
      s.segment<3>(o + 7) = b.vel;
      s.segment<3>(o + 10) = b.omega;
    } else {
      s.segment<3>(o + 3) = b.vel;
    }
  }
  return s;
}

Quat System::orientation(int b, const Eigen::VectorXd& s) const {
  if (b < 0) return Quat::Identity();
  const Body& body = scene_.bodies[static_cast<std::size_t>(b)];
  const int m = moving_[static_cast<std::size_t>(b)];
  if (m < 0 || body.kind == BodyKind::particle) return m < 0 ? body.quat : Quat::Identity();
  const int o = offset_[static_cast<std::size_t>(m)];
  return Quat(s[o + 3], s[o + 4], s[o + 5], s[o + 6]).normalized();
}

BodyKin System::kinematics(int b, const Eigen::VectorXd& s) const {
  BodyKin k;
  if (b < 0) return k;
  const Body& body = scene_.bodies[static_cast<std::size_t>(b)];
  const int m = moving_[static_cast<std::size_t>(b)];
  if (m < 0) {
    k.p = body.pos;
    k.R = body.quat.toRotationMatrix();
    return k;
  }
  const int o = offset_[static_cast<std::size_t>(m)];
  k.p = s.segment<3>(o);
  if (body.kind == BodyKind::rigid) {
    // Intermediate RK stages carry unnormalised q: R from q/|q| (docs/lmfsim.md §6).
    k.R = Quat(s[o + 3], s[o + 4], s[o + 5], s[o + 6]).normalized().toRotationMatrix();
    k.v = s.segment<3>(o + 7);
    k.w = s.segment<3>(o + 10);
    k.dof = 6;
  } else {
    k.v = s.segment<3>(o + 3);
    k.dof = 3;
  }
  return k;
}

void System::compute_kinematics(const Eigen::VectorXd& s, std::vector<BodyKin>& kin) const {
  kin.resize(scene_.bodies.size());
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) kin[i] = kinematics(static_cast<int>(i), s);
}

void System::collect_active() {
  active_.clear();
  for (std::size_t j = 0; j < scene_.constraints.size(); ++j)
    if (scene_.constraints[j].active) active_.push_back(static_cast<int>(j));
  evals_.resize(active_.size());
  cons_.resize(active_.size());
  topology_changed_ = true;
}

void System::kinematic_rate(double t, const Eigen::VectorXd& s, Eigen::VectorXd& ds) const {
  if (ds.size() != n_state_) ds.setZero(n_state_);
  for (std::size_t m = 0; m < moving_body_.size(); ++m) {
    const Body& b = scene_.bodies[static_cast<std::size_t>(moving_body_[m])];
    const int o = offset_[m];
    if (b.kind == BodyKind::rigid) {
      ds.segment<3>(o) = s.segment<3>(o + 7);
      // qdot = 1/2 (0, w) (x) q
      const Vec3 w = s.segment<3>(o + 10);
      const double qw = s[o + 3];
      const Vec3 qv = s.segment<3>(o + 4);
      ds[o + 3] = -0.5 * w.dot(qv);
      ds.segment<3>(o + 4) = 0.5 * (qw * w + w.cross(qv));
    } else {
      ds.segment<3>(o) = s.segment<3>(o + 3);
    }
  }
  for (std::size_t f = 0; f < scene_.forces.size(); ++f) {
    const int po = pid_offset_[f];
    if (po < 0) continue;
    const ForceElement& fe = scene_.forces[f];
    if (!fe.active) {
      ds.segment<3>(po).setZero();
      continue;
    }
    const BodyKin k = kinematics(fe.a, s);
    ds.segment<3>(po) = fe.goal.at(t) - world_point(k, fe.pa);
  }
}

void System::build_problem(double t, const Eigen::VectorXd& s) {
  compute_kinematics(s, kin_);
  // M^-1 is read only by the dense solver, the penalty formulation and force
  // stabilisation; the Baraff solver factors M itself, so it is not formed for it.
  const bool need_minv = scene_.sim.solver == SolverKind::dense || scene_.sim.formulation == Formulation::penalty ||
                         scene_.sim.stab == Stabilization::force;
  // Mass blocks and applied forces (gravity, gyroscopic term, force elements).
  for (std::size_t m = 0; m < moving_body_.size(); ++m) {
    const int bi = moving_body_[m];
    const Body& b = scene_.bodies[static_cast<std::size_t>(bi)];
    const BodyKin& k = kin_[static_cast<std::size_t>(bi)];
    SolveBody& sb = bodies_[m];
    sb.dof = k.dof;
    sb.M.setZero(k.dof, k.dof);
    sb.F.setZero(k.dof);
    sb.M.topLeftCorner<3, 3>() = b.mass * Mat3::Identity();
    sb.F.head<3>() = b.mass * scene_.gravity;
    if (need_minv) {
      sb.Minv.setZero(k.dof, k.dof);
      sb.Minv.topLeftCorner<3, 3>() = Mat3::Identity() / b.mass;
    }
    if (k.dof == 6) {
      const Mat3 Iw = k.R * b.inertia * k.R.transpose();
      sb.M.bottomRightCorner<3, 3>() = Iw;
      if (need_minv)
        sb.Minv.bottomRightCorner<3, 3>() = k.R * inertia_inv_[static_cast<std::size_t>(bi)] * k.R.transpose();
      sb.F.tail<3>() = -k.w.cross(Iw * k.w);
    }
  }
  auto apply = [&](int body, const Vec3& point_offset_world, const Vec3& f, const Vec3& tau) {
    if (body < 0) return;
    const int m = moving_[static_cast<std::size_t>(body)];
    if (m < 0) return;
    SolveBody& sb = bodies_[static_cast<std::size_t>(m)];
    sb.F.head<3>() += f;
    if (sb.dof == 6) sb.F.tail<3>() += point_offset_world.cross(f) + tau;
  };
  for (std::size_t fi = 0; fi < scene_.forces.size(); ++fi) {
    const ForceElement& fe = scene_.forces[fi];
    if (!fe.active) continue;
    switch (fe.type) {
      case ForceType::spring: {
        const BodyKin &ka = fe.a < 0 ? BodyKin() : kin_[static_cast<std::size_t>(fe.a)];
        const BodyKin &kb = fe.b < 0 ? BodyKin() : kin_[static_cast<std::size_t>(fe.b)];
        const Vec3 wa = ka.R * fe.pa, wb = kb.R * fe.pb;
        const Vec3 d = (kb.p + wb) - (ka.p + wa);
        const double len = d.norm();
        if (len < 1e-15) break;
        const Vec3 e = d / len;
        const double rate = e.dot((kb.v + kb.w.cross(wb)) - (ka.v + ka.w.cross(wa)));
        const Vec3 fb = -(fe.k * (len - fe.rest) + fe.d * rate) * e;
        apply(fe.b, wb, fb, Vec3::Zero());
        apply(fe.a, wa, -fb, Vec3::Zero());
        break;
      }
      case ForceType::drag:
        for (std::size_t m = 0; m < moving_body_.size(); ++m) {
          const int bi = moving_body_[m];
          if (fe.a >= 0 && fe.a != bi) continue;
          const BodyKin& k = kin_[static_cast<std::size_t>(bi)];
          apply(bi, Vec3::Zero(), -fe.linear * k.v, -fe.angular * k.w);
        }
        break;
      case ForceType::constant: {
        const BodyKin& k = kin_[static_cast<std::size_t>(fe.a)];
        const Vec3 f = fe.body_frame ? Vec3(k.R * fe.force) : fe.force;
        const Vec3 tau = fe.body_frame ? Vec3(k.R * fe.torque) : fe.torque;
        apply(fe.a, k.R * fe.pa, f, tau);
        break;
      }
      case ForceType::pid: {
        const BodyKin& k = kin_[static_cast<std::size_t>(fe.a)];
        const Vec3 w = k.R * fe.pa;
        const Vec3 xe = fe.goal.at(t) - (k.p + w);
        const Vec3 ve = fe.goal.rate(t) - (k.v + k.w.cross(w));
        const Vec3 integral = s.segment<3>(pid_offset_[fi]);
        const Vec3 f = fe.kx.cwiseProduct(xe) + fe.kv.cwiseProduct(ve) + fe.ki.cwiseProduct(integral);
        apply(fe.a, w, f, Vec3::Zero());
        break;
      }
    }
  }
  // Constraints: evaluate, stabilise (docs/lmfsim.md §4 eq. (6)).
  const SimSettings& sim = scene_.sim;
  const bool baumgarte = sim.stab == Stabilization::baumgarte;
  info_ = EvalInfo();
  for (std::size_t q = 0; q < active_.size(); ++q) {
    const Constraint& c = scene_.constraints[static_cast<std::size_t>(active_[q])];
    static const BodyKin world;
    const BodyKin& ka = c.a < 0 ? world : kin_[static_cast<std::size_t>(c.a)];
    const BodyKin& kb = c.b < 0 ? world : kin_[static_cast<std::size_t>(c.b)];
    ConstraintEval& e = evals_[q];
    eval_constraint(c, ka, kb, t, e);
    SolveConstraint& sc = cons_[q];
    sc.a = c.a < 0 ? -1 : moving_[static_cast<std::size_t>(c.a)];
    sc.b = c.b < 0 ? -1 : moving_[static_cast<std::size_t>(c.b)];
    sc.Ja = &e.Ja;
    sc.Jb = &e.Jb;
    sc.c = e.c;
    info_.rows += e.rows;
    if (is_velocity_constraint(c.type)) {
      info_.Cv_max = std::max(info_.Cv_max, e.C.cwiseAbs().maxCoeff());
      if (baumgarte) sc.c += 2 * sim.alpha * e.C;
    } else {
      info_.C_max = std::max(info_.C_max, e.C.cwiseAbs().maxCoeff());
      info_.Cdot_max = std::max(info_.Cdot_max, e.Cdot.cwiseAbs().maxCoeff());
      if (baumgarte) sc.c += 2 * sim.alpha * e.Cdot + sim.beta * sim.beta * e.C;
    }
  }
}

void System::derivative(double t, const Eigen::VectorXd& s, Eigen::VectorXd& ds) {
  build_problem(t, s);
  kinematic_rate(t, s, ds);
  const SimSettings& sim = scene_.sim;
  std::fill(lambda_.begin(), lambda_.end(), Vecx());
  if (sim.formulation == Formulation::penalty) {
    // Springs along the constraint gradients: F = -kappa J^T (w0^2 C + 2 zeta w0 Cdot).
    for (std::size_t q = 0; q < active_.size(); ++q) {
      const Constraint& c = scene_.constraints[static_cast<std::size_t>(active_[q])];
      const ConstraintEval& e = evals_[q];
      const Vecx g = is_velocity_constraint(c.type)
                         ? Vecx(-sim.kappa * 2 * sim.zeta * sim.omega0 * e.C)
                         : Vecx(-sim.kappa * (sim.omega0 * sim.omega0 * e.C + 2 * sim.zeta * sim.omega0 * e.Cdot));
      lambda_[static_cast<std::size_t>(active_[q])] = g;
      for (int side = 0; side < 2; ++side) {
        const int m = side == 0 ? cons_[q].a : cons_[q].b;
        if (m < 0) continue;
        SolveBody& sb = bodies_[static_cast<std::size_t>(m)];
        sb.F += (side == 0 ? e.Ja : e.Jb).leftCols(sb.dof).transpose() * g;
      }
    }
    for (std::size_t m = 0; m < moving_body_.size(); ++m) {
      const int o = offset_[m];
      const Vecx a = bodies_[m].Minv * bodies_[m].F;
      ds.segment(o + (bodies_[m].dof == 6 ? 7 : 3), bodies_[m].dof) = a;
    }
    return;
  }
  const auto t0 = SteadyClock::now();
  solver_->solve(bodies_, cons_, topology_changed_, result_);
  topology_changed_ = false;
  info_.solve_us = 1000.0 * ms_since(t0);
  info_.rank_deficiency = result_.rank_deficiency;
  info_.residual = result_.residual;
  if (!(result_.residual <= 1e-6))
    throw runtime_failure("conflicting constraints: rows cannot be satisfied (rank deficiency {}, relative residual {:.3g}) (t={:.6g})",
                          result_.rank_deficiency, result_.residual, t);
  for (std::size_t q = 0; q < active_.size(); ++q) lambda_[static_cast<std::size_t>(active_[q])] = result_.lambda[q];
  for (std::size_t m = 0; m < moving_body_.size(); ++m)
    ds.segment(offset_[m] + (bodies_[m].dof == 6 ? 7 : 3), bodies_[m].dof) = result_.acc[m];
  if (sim.stab == Stabilization::force) {
    // F_s = -J^T S (2 alpha Cdot + beta^2 C), S = effective mass per row.
    for (std::size_t q = 0; q < active_.size(); ++q) {
      const Constraint& c = scene_.constraints[static_cast<std::size_t>(active_[q])];
      const ConstraintEval& e = evals_[q];
      Vecx g = is_velocity_constraint(c.type) ? Vecx(2 * sim.alpha * e.C)
                                              : Vecx(2 * sim.alpha * e.Cdot + sim.beta * sim.beta * e.C);
      for (int r = 0; r < e.rows; ++r) {
        double k = 0;
        for (int side = 0; side < 2; ++side) {
          const int m = side == 0 ? cons_[q].a : cons_[q].b;
          if (m < 0) continue;
          const SolveBody& sb = bodies_[static_cast<std::size_t>(m)];
          const auto row = (side == 0 ? e.Ja : e.Jb).row(r).head(sb.dof);
          k += row * sb.Minv * row.transpose();
        }
        g[r] = k > 0 ? -g[r] / k : 0.0;
      }
      for (int side = 0; side < 2; ++side) {
        const int m = side == 0 ? cons_[q].a : cons_[q].b;
        if (m < 0) continue;
        const SolveBody& sb = bodies_[static_cast<std::size_t>(m)];
        ds.segment(offset_[static_cast<std::size_t>(m)] + (sb.dof == 6 ? 7 : 3), sb.dof) +=
            sb.Minv * ((side == 0 ? e.Ja : e.Jb).leftCols(sb.dof).transpose() * g);
      }
    }
  }
}

void System::normalize(Eigen::VectorXd& s) const {
  for (std::size_t m = 0; m < moving_body_.size(); ++m) {
    if (scene_.bodies[static_cast<std::size_t>(moving_body_[m])].kind != BodyKind::rigid) continue;
    s.segment<4>(offset_[m] + 3).normalize();
  }
}

void System::project(double t, Eigen::VectorXd& s) {
  // Mass-weighted Gauss-Newton: dx = -M^-1 J^T (J M^-1 J^T)^+ C, reusing the solver
  // with F = 0 and c = C (its answer is exactly dx); then the same on velocities.
  const auto solve_correction = [&](bool velocities) {
    build_problem(t, s);
    for (auto& sb : bodies_) sb.F.setZero(sb.dof);
    for (std::size_t q = 0; q < active_.size(); ++q) {
      const Constraint& c = scene_.constraints[static_cast<std::size_t>(active_[q])];
      const bool vrow = is_velocity_constraint(c.type);
      if (velocities) cons_[q].c = vrow ? evals_[q].C : evals_[q].Cdot;
      else cons_[q].c = vrow ? Vecx(Vecx::Zero(evals_[q].rows)) : evals_[q].C;
    }
    solver_->solve(bodies_, cons_, topology_changed_, result_);
    topology_changed_ = false;
  };
  for (int it = 0; it < 3; ++it) {
    if (max_violation(t, s) < 1e-14) break;
    solve_correction(false);
    for (std::size_t m = 0; m < moving_body_.size(); ++m) {
      const int o = offset_[m];
      const Vecx& dx = result_.acc[m];
      s.segment<3>(o) += dx.head<3>();
      if (bodies_[m].dof == 6) {
        const Vec3 dth = dx.tail<3>();
        const double ang = dth.norm();
        const Quat dq = ang > 0 ? Quat(Eigen::AngleAxisd(ang, dth / ang)) : Quat::Identity();
        Quat q(s[o + 3], s[o + 4], s[o + 5], s[o + 6]);
        q = (dq * q).normalized();
        s.segment<4>(o + 3) << q.w(), q.x(), q.y(), q.z();
      }
    }
  }
  solve_correction(true);
  for (std::size_t m = 0; m < moving_body_.size(); ++m)
    s.segment(offset_[m] + (bodies_[m].dof == 6 ? 7 : 3), bodies_[m].dof) += result_.acc[m];
}

double System::max_violation(double t, const Eigen::VectorXd& s) const {
  double worst = 0;
  ConstraintEval e;
  const BodyKin world;
  for (int j : active_) {
    const Constraint& c = scene_.constraints[static_cast<std::size_t>(j)];
    if (is_velocity_constraint(c.type)) continue;
    const BodyKin ka = c.a < 0 ? world : kinematics(c.a, s), kb = c.b < 0 ? world : kinematics(c.b, s);
    if (c.type == ConstraintType::ball) {
      // Checked after every step: only C = P_a - P_b is needed, not the Jacobian rows
      // and acceleration terms that eval_constraint also forms (same arithmetic for C).
      const Vec3 C = (ka.p + ka.R * c.pa) - (kb.p + kb.R * c.pb);
      worst = std::max(worst, C.cwiseAbs().maxCoeff());
      continue;
    }
    eval_constraint(c, ka, kb, t, e);
    worst = std::max(worst, e.C.cwiseAbs().maxCoeff());
  }
  return worst;
}

Energy System::energy(const Eigen::VectorXd& s) const {
  Energy en;
  for (int bi : moving_body_) {
    const Body& b = scene_.bodies[static_cast<std::size_t>(bi)];
    const BodyKin k = kinematics(bi, s);
    en.T += 0.5 * b.mass * k.v.squaredNorm();
    if (k.dof == 6) en.T += 0.5 * k.w.dot(k.R * b.inertia * k.R.transpose() * k.w);
    en.U -= b.mass * scene_.gravity.dot(k.p);
  }
  for (const ForceElement& fe : scene_.forces) {
    if (!fe.active || fe.type != ForceType::spring) continue;
    const BodyKin ka = kinematics(fe.a, s), kb = kinematics(fe.b, s);
    const double len = (world_point(kb, fe.pb) - world_point(ka, fe.pa)).norm();
    en.U += 0.5 * fe.k * (len - fe.rest) * (len - fe.rest);
  }
  return en;
}

double System::energy_scale() const { return energy_scale_; }

bool System::conservative() const {
  for (const ForceElement& f : scene_.forces)
    if (f.type != ForceType::spring || f.d != 0) return false;
  for (const Constraint& c : scene_.constraints)
    if (c.type == ConstraintType::motor || c.type == ConstraintType::path) return false;
  return true;
}

std::vector<Vec6> System::constraint_wrenches(double, const Eigen::VectorXd& s) const {
  std::vector<Vec6> w(scene_.bodies.size(), Vec6::Zero());
  for (std::size_t q = 0; q < active_.size(); ++q) {
    const auto& lam = lambda_[static_cast<std::size_t>(active_[q])];
    if (lam.size() != evals_[q].rows) continue;
    const Constraint& c = scene_.constraints[static_cast<std::size_t>(active_[q])];
    for (int side = 0; side < 2; ++side) {
      const int b = side == 0 ? c.a : c.b;
      if (b < 0) continue;
      const Vec6 f = (side == 0 ? evals_[q].Ja : evals_[q].Jb).transpose() * lam;
      w[static_cast<std::size_t>(b)] += f;
    }
  }
  (void)s;
  return w;
}

int System::constraint_index(const std::string& name) const {
  for (std::size_t j = 0; j < scene_.constraints.size(); ++j)
    if (scene_.constraints[j].name == name) return static_cast<int>(j);
  return -1;
}
int System::force_index(const std::string& name) const {
  for (std::size_t j = 0; j < scene_.forces.size(); ++j)
    if (!name.empty() && scene_.forces[j].name == name) return static_cast<int>(j);
  return -1;
}
int System::body_index(const std::string& name) const {
  for (std::size_t j = 0; j < scene_.bodies.size(); ++j)
    if (scene_.bodies[j].name == name) return static_cast<int>(j);
  return -1;
}

void System::check_event(const Event& e) const {
  const auto dot = e.target.find('.');
  const std::string name = e.target.substr(0, dot);
  const std::string field = dot == std::string::npos ? "" : e.target.substr(dot + 1);
  switch (e.action) {
    case EventAction::activate:
    case EventAction::deactivate:
      if (constraint_index(name) < 0 && force_index(name) < 0)
        throw bad_input("event at t={}: unknown constraint or force '{}'", e.t, name);
      return;
    case EventAction::set: {
      const int b = body_index(name);
      if (b < 0) throw bad_input("event at t={}: unknown body '{}'", e.t, name);
      const std::size_t want = field == "quat" ? 4 : 3;
      if (field != "pos" && field != "vel" && field != "omega" && field != "quat")
        throw bad_input("event at t={}: cannot set '{}' (pos, quat, vel, omega)", e.t, e.target);
      if (e.value.size() != want) throw bad_input("event at t={}: '{}' needs {} values", e.t, e.target, want);
      if (moving_[static_cast<std::size_t>(b)] < 0) throw bad_input("event at t={}: body '{}' is fixed", e.t, name);
      return;
    }
    case EventAction::set_param: {
      const int c = constraint_index(name), f = force_index(name);
      static const char* cfields[] = {"omega", "length", "radius"};
      static const char* ffields[] = {"k", "d", "rest", "linear", "angular", "goal", "force", "torque"};
      bool ok = false;
      if (c >= 0) for (const char* s : cfields) ok = ok || field == s;
      if (f >= 0) for (const char* s : ffields) ok = ok || field == s;
      if (!ok) throw bad_input("event at t={}: unknown parameter '{}'", e.t, e.target);
      if (e.value.empty()) throw bad_input("event at t={}: '{}' needs a value", e.t, e.target);
      return;
    }
  }
}

void System::apply_event(const Event& e, Eigen::VectorXd& s) {
  const auto dot = e.target.find('.');
  const std::string name = e.target.substr(0, dot);
  const std::string field = dot == std::string::npos ? "" : e.target.substr(dot + 1);
  switch (e.action) {
    case EventAction::activate:
    case EventAction::deactivate: {
      const bool on = e.action == EventAction::activate;
      const int c = constraint_index(name);
      if (c >= 0) {
        if (scene_.constraints[static_cast<std::size_t>(c)].active != on) {
          scene_.constraints[static_cast<std::size_t>(c)].active = on;
          collect_active();
        }
      } else {
        scene_.forces[static_cast<std::size_t>(force_index(name))].active = on;
      }
      return;
    }
    case EventAction::set: {
      const int b = body_index(name);
      const int m = moving_[static_cast<std::size_t>(b)];
      const int o = offset_[static_cast<std::size_t>(m)];
      const bool rigid = scene_.bodies[static_cast<std::size_t>(b)].kind == BodyKind::rigid;
      const Vec3 v = e.value.size() >= 3 ? Vec3(e.value[0], e.value[1], e.value[2]) : Vec3::Zero();
      if (field == "pos") s.segment<3>(o) = v;
      else if (field == "vel") s.segment<3>(o + (rigid ? 7 : 3)) = v;
      else if (field == "omega" && rigid) s.segment<3>(o + 10) = v;
      else if (field == "quat" && rigid) {
        Eigen::Vector4d q(e.value[0], e.value[1], e.value[2], e.value[3]);
        if (!(q.norm() > 0)) throw bad_input("event at t={}: zero quaternion", e.t);
        s.segment<4>(o + 3) = q.normalized();
      }
      return;
    }
    case EventAction::set_param: {
      const double v = e.value[0];
      const int c = constraint_index(name);
      if (c >= 0) {
        Constraint& con = scene_.constraints[static_cast<std::size_t>(c)];
        if (field == "omega") con.omega = Signal{v, Spline()};
        else if (field == "length") con.length = v;
        else if (field == "radius") con.radius = v;
        return;
      }
      ForceElement& f = scene_.forces[static_cast<std::size_t>(force_index(name))];
      const Vec3 v3 = e.value.size() >= 3 ? Vec3(e.value[0], e.value[1], e.value[2]) : Vec3::Constant(v);
      if (field == "k") f.k = v;
      else if (field == "d") f.d = v;
      else if (field == "rest") f.rest = v;
      else if (field == "linear") f.linear = v;
      else if (field == "angular") f.angular = v;
      else if (field == "force") f.force = v3;
      else if (field == "torque") f.torque = v3;
      else if (field == "goal") for (int k = 0; k < 3; ++k) f.goal.c[static_cast<std::size_t>(k)] = Signal{v3[k], Spline()};
      return;
    }
  }
}

Eigen::MatrixXd System::jacobian(double t, const Eigen::VectorXd& s, Eigen::VectorXd* Cout) const {
  int m = 0;
  for (int j : active_) m += constraint_rows(scene_.constraints[static_cast<std::size_t>(j)].type);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, n_dof_);
  if (Cout) Cout->setZero(m);
  std::vector<int> dof_off(moving_body_.size(), 0);
  for (std::size_t i = 1; i < moving_body_.size(); ++i)
    dof_off[i] = dof_off[i - 1] + (scene_.bodies[static_cast<std::size_t>(moving_body_[i - 1])].kind == BodyKind::rigid ? 6 : 3);
  int row = 0;
  ConstraintEval e;
  const BodyKin world;
  for (int j : active_) {
    const Constraint& c = scene_.constraints[static_cast<std::size_t>(j)];
    eval_constraint(c, c.a < 0 ? world : kinematics(c.a, s), c.b < 0 ? world : kinematics(c.b, s), t, e);
    for (int side = 0; side < 2; ++side) {
      const int b = side == 0 ? c.a : c.b;
      if (b < 0 || moving_[static_cast<std::size_t>(b)] < 0) continue;
      const int mi = moving_[static_cast<std::size_t>(b)];
      const int dof = scene_.bodies[static_cast<std::size_t>(b)].kind == BodyKind::rigid ? 6 : 3;
      J.block(row, dof_off[static_cast<std::size_t>(mi)], e.rows, dof) += (side == 0 ? e.Ja : e.Jb).leftCols(dof);
    }
    if (Cout) Cout->segment(row, e.rows) = e.C;
    row += e.rows;
  }
  return J;
}

}  // namespace fest::lmfsim

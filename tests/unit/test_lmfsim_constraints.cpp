// Constraint calculus (docs/lmfsim.md §2): J xdot equals dC/dt and c equals Cddot along a free
// motion (constant v, constant omega), for every constraint type, at random states.
#include <gtest/gtest.h>

#include <random>

#include "lmfsim/constraint_eval.hpp"

using namespace fest::lmfsim;

namespace {

struct Motion {
  Vec3 p0, v, w;
  Quat q0;
  BodyKin at(double t) const {
    BodyKin k;
    k.p = p0 + v * t;
    const double ang = w.norm() * t;
    const Quat dq = ang != 0 ? Quat(Eigen::AngleAxisd(ang, w.normalized())) : Quat::Identity();
    k.R = (dq * q0).toRotationMatrix();
    k.v = v;
    k.w = w;
    k.dof = 6;
    return k;
  }
};

Vec3 rnd3(std::mt19937& g, double s = 1) {
  std::uniform_real_distribution<double> u(-s, s);
  return {u(g), u(g), u(g)};
}

Constraint make(ConstraintType t, std::mt19937& g, bool b_world) {
  Constraint c;
  c.type = t;
  c.a = 0;
  c.b = b_world ? kWorld : 1;
  c.pa = rnd3(g, 0.5);
  c.pb = rnd3(g, 0.5);
  c.axis_a = rnd3(g).normalized();
  c.axis_b = rnd3(g).normalized();
  c.length = 1.3;
  c.origin = rnd3(g);
  c.direction = rnd3(g).normalized();
  c.radius = 0.7;
  c.rest = Quat(Eigen::AngleAxisd(0.3, rnd3(g).normalized()));
  c.path.c[0].keys = Spline({0, 1, 2, 3}, {0, 0.5, -0.2, 0.1});
  c.path.c[1].keys = Spline({0, 1, 2, 3}, {1, 0.3, 0.2, 0.8});
  c.path.c[2].keys = Spline({0, 1, 2, 3}, {0, 0.1, 0.9, 0.4});
  c.omega.keys = Spline({0, 1, 2, 3}, {0, 2, 1, 3});
  return c;
}

// Rows whose C is exact (orientation-lock rows are first-order by design, docs/lmfsim.md §2).
bool exact_row(ConstraintType t, int r) {
  if (t == ConstraintType::weld) return r < 3;
  if (t == ConstraintType::slider) return r >= 3;
  return true;
}

}  // namespace

TEST(LmfsimConstraints, JacobianAndBiasMatchFiniteDifferences) {
  std::mt19937 g(7);
  const ConstraintType types[] = {ConstraintType::ball, ConstraintType::hinge, ConstraintType::axis_parallel,
                                  ConstraintType::slider, ConstraintType::weld, ConstraintType::distance,
                                  ConstraintType::point_on_plane, ConstraintType::point_on_line,
                                  ConstraintType::point_on_circle, ConstraintType::path};
  for (ConstraintType type : types) {
    for (int trial = 0; trial < 100; ++trial) {
      const bool world = trial % 3 == 0 || type == ConstraintType::path || type == ConstraintType::point_on_plane ||
                         type == ConstraintType::point_on_line || type == ConstraintType::point_on_circle;
      const Constraint c = make(type, g, world);
      Motion ma{rnd3(g), rnd3(g), rnd3(g, 2), Quat(Eigen::AngleAxisd(1.0, rnd3(g).normalized()))};
      Motion mb{rnd3(g), rnd3(g), rnd3(g, 2), Quat(Eigen::AngleAxisd(2.0, rnd3(g).normalized()))};
      if (world) mb = Motion{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Quat::Identity()};
      const double t0 = 1.3, eps = 1e-5;
      auto eval = [&](double dt) {
        ConstraintEval e;
        BodyKin kb = mb.at(dt);
        if (world) kb = BodyKin();
        eval_constraint(c, ma.at(dt), kb, t0 + dt, e);
        return e;
      };
      const ConstraintEval e0 = eval(0), ep = eval(eps), em = eval(-eps);
      Vec6 xa, xb;
      xa << ma.v, ma.w;
      xb << mb.v, mb.w;
      for (int r = 0; r < e0.rows; ++r) {
        if (!exact_row(type, r)) continue;
        const double dC = (ep.C[r] - em.C[r]) / (2 * eps);
        const double scale = 1 + std::abs(dC);
        EXPECT_NEAR(e0.Cdot[r], dC, 1e-6 * scale) << constraint_type_name(type) << " row " << r;
        // Time-dependent rows add dC/dt explicitly; J xdot alone is Cdot minus that.
        if (type != ConstraintType::path) {
          const double Jx = e0.Ja.row(r).dot(xa) + (world ? 0.0 : e0.Jb.row(r).dot(xb));
          EXPECT_NEAR(Jx, dC, 1e-6 * scale) << constraint_type_name(type) << " row " << r;
        }
        // c = Cddot along the free motion (xdd = 0); second difference with a larger step.
        const double h = 1e-4;
        const ConstraintEval e2p = eval(h), e2m = eval(-h);
        const double ddC = (e2p.C[r] - 2 * e0.C[r] + e2m.C[r]) / (h * h);
        EXPECT_NEAR(e0.c[r], ddC, 1e-5 * (1 + std::abs(ddC)) + 2e-6) << constraint_type_name(type) << " row " << r;
      }
    }
  }
}

TEST(LmfsimConstraints, VelocityRowsAreLinearInVelocity) {
  std::mt19937 g(11);
  for (ConstraintType type : {ConstraintType::motor, ConstraintType::knife_edge}) {
    for (int trial = 0; trial < 100; ++trial) {
      Constraint c = make(type, g, type == ConstraintType::knife_edge);
      Motion ma{rnd3(g), rnd3(g), rnd3(g, 2), Quat(Eigen::AngleAxisd(1.0, rnd3(g).normalized()))};
      Motion mb{rnd3(g), rnd3(g), rnd3(g, 2), Quat(Eigen::AngleAxisd(2.0, rnd3(g).normalized()))};
      const bool world = c.b == kWorld;
      const double t0 = 0.7;
      auto eval = [&](const Motion& a, const Motion& b, double dt) {
        ConstraintEval e;
        eval_constraint(c, a.at(dt), world ? BodyKin() : b.at(dt), t0 + dt, e);
        return e;
      };
      const ConstraintEval e0 = eval(ma, mb, 0);
      // J = dC_v / dxdot by differences in each velocity component of body a.
      for (int k = 0; k < 6; ++k) {
        Motion mp = ma, mm = ma;
        const double eps = 1e-6;
        if (k < 3) mp.v[k] += eps, mm.v[k] -= eps;
        else mp.w[k - 3] += eps, mm.w[k - 3] -= eps;
        // Evaluate at dt = 0 so the position is unchanged.
        const double d = (eval(mp, mb, 0).C[0] - eval(mm, mb, 0).C[0]) / (2 * eps);
        EXPECT_NEAR(e0.Ja(0, k), d, 1e-6 * (1 + std::abs(d))) << constraint_type_name(type);
      }
      // c = dC_v/dt along the free motion (constant velocities).
      const double eps = 1e-5;
      const double dC = (eval(ma, mb, eps).C[0] - eval(ma, mb, -eps).C[0]) / (2 * eps);
      EXPECT_NEAR(e0.c[0], dC, 1e-6 * (1 + std::abs(dC))) << constraint_type_name(type);
    }
  }
}

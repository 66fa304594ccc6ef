// Analytic and reference cases of docs/lmfsim.md §7: pendulum periods, normal modes, the chaotic
// double pendulum against the reduced-coordinate reference, constraint drift with and
// without stabilisation, the Baumgarte decay law, the four-bar against its 1-DOF
// equation, rod tension, a motor's first-order feedback and a free body's invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "lmfsim/simulate.hpp"
#include "lmfsim_scenes.hpp"

using namespace lmfsim_test;

namespace {

// Runs the scene and calls `probe(t, s)` at every step.
void run(System& sys, const std::function<void(double, const Eigen::VectorXd&)>& probe) {
  simulate(sys, [&](int, double t, const Eigen::VectorXd& s) { probe(t, s); });
}

// Mean period from the times where f crosses zero (either way; linear interpolation):
// successive crossings are half a period apart.
double period(const std::vector<double>& t, const std::vector<double>& f) {
  std::vector<double> cross;
  for (std::size_t i = 1; i < f.size(); ++i)
    if ((f[i - 1] < 0 && f[i] >= 0) || (f[i - 1] > 0 && f[i] <= 0))
      cross.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-f[i - 1]) / (f[i] - f[i - 1]));
  EXPECT_GE(cross.size(), 3u);
  if (cross.size() < 2) return 0;
  return 2 * (cross.back() - cross.front()) / static_cast<double>(cross.size() - 1);
}

double pendulum_period(double amplitude) {
  Scene s = particle_chain({amplitude});
  s.sim.t_end = 4.5;
  s.sim.stab = Stabilization::baumgarte;
  System sys(s);
  std::vector<double> t, x;
  // Angular rate about y (z vx - x vz): crosses zero at the turning points with slope g sin(amplitude).
  run(sys, [&](double tt, const Eigen::VectorXd& st) { t.push_back(tt); x.push_back(st[2] * st[3] - st[0] * st[5]); });
  return period(t, x);
}

Scene chaotic_double_pendulum(double dt, double ab, Integrator integ = Integrator::rk4) {
  Scene s = particle_chain({kPi / 2, kPi / 2});
  s.sim.t_end = 10;
  s.sim.dt = dt;
  s.sim.integrator = integ;
  s.sim.alpha = s.sim.beta = ab;
  s.sim.stab = ab > 0 ? Stabilization::baumgarte : Stabilization::none;
  s.sim.max_violation = 1;
  return s;
}

}  // namespace

TEST(LmfsimAnalytic, PendulumSmallAmplitudePeriod) {
  EXPECT_NEAR(pendulum_period(1e-3), 2 * kPi * std::sqrt(1 / 9.81), 1e-5);
  EXPECT_NEAR(pendulum_period(1e-3), 2.006067, 1e-5);
}

TEST(LmfsimAnalytic, PendulumNinetyDegreePeriod) {
  // T = 4 sqrt(L/g) K(sin 45 deg) = 2.367842 s.
  EXPECT_NEAR(pendulum_period(kPi / 2), 2.367842, 1e-5);
}

TEST(LmfsimAnalytic, UniformRodPendulumPeriod) {
  // Thin rod (box 1 x 1e-3 x 1e-3) hinged at its end: T = 2 pi sqrt(2L / 3g) = 1.637947 s;
  // the rod's finite thickness changes I by 1e-6 relative.
  Scene s;
  const double a = 1e-3;
  s.bodies.push_back(box_body("rod", Vec3(0.5 * std::sin(a), 0, -0.5 * std::cos(a)), Vec3(1, 1e-3, 1e-3), 1,
                              Quat(Eigen::AngleAxisd(kPi / 2 - a, Vec3::UnitY()))));
  s.constraints.push_back(hinge("h", kWorld, Vec3::Zero(), 0, Vec3(-0.5, 0, 0)));
  s.sim.t_end = 3.5;
  s.sim.every = 1;
  System sys(s);
  std::vector<double> t, x;
  run(sys, [&](double tt, const Eigen::VectorXd& st) { t.push_back(tt); x.push_back(st[7]); });
  EXPECT_NEAR(period(t, x), 1.637947, 1e-5);
}

TEST(LmfsimAnalytic, DoublePendulumNormalModes) {
  // omega^2 = (2 -+ sqrt 2) g / l for equal masses and lengths.
  for (int mode = 0; mode < 2; ++mode) {
    const double th1 = 1e-3, th2 = (mode == 0 ? 1 : -1) * std::sqrt(2.0) * th1;
    // th are absolute angles of each rod from the vertical: rod 2's angle is th2.
    Scene s = particle_chain({th1, th2});
    s.sim.t_end = 20;
    System sys(s);
    std::vector<double> t, f, other;
    double excited = 0, leak = 0;
    run(sys, [&](double tt, const Eigen::VectorXd& st) {
      const double a1 = std::atan2(st[0], -st[2]);
      const Vec3 d = st.segment<3>(6) - st.segment<3>(0);
      const double a2 = std::atan2(d.x(), -d.z());
      t.push_back(tt);
      f.push_back(a1);
      // Modal coordinates: mode 1 ~ (1, sqrt2), mode 2 ~ (1, -sqrt2).
      const double q1 = (a1 * std::sqrt(2.0) + a2) / (2 * std::sqrt(2.0)), q2 = (a1 * std::sqrt(2.0) - a2) / (2 * std::sqrt(2.0));
      excited = std::max(excited, std::abs(mode == 0 ? q1 : q2));
      leak = std::max(leak, std::abs(mode == 0 ? q2 : q1));
    });
    const double w = 2 * kPi / period(t, f);
    const double expect = mode == 0 ? 2.397199 : 5.787351;
    EXPECT_NEAR(w, expect, 1e-4 * expect) << "mode " << mode;
    EXPECT_LT(leak, 1e-3 * excited) << "mode " << mode;
  }
}

TEST(LmfsimAnalytic, ChaoticDoublePendulumMatchesReducedReference) {
  System sys(chaotic_double_pendulum(1e-3, 10));
  Eigen::Vector3d tip;
  run(sys, [&](double, const Eigen::VectorXd& st) { tip = st.segment<3>(6); });
  // Reduced coordinates, RK4 h = 1e-4 (independent formulation).
  ReducedChain ch;
  ch.links = {ChainLink{1, 1, 1, 0}, ChainLink{1, 1, 1, 0}};
  Eigen::VectorXd th(2), thd = Eigen::VectorXd::Zero(2);
  th << kPi / 2, kPi / 2;
  for (int k = 0; k < 100000; ++k) ch.step_rk4(th, thd, 1e-4);
  const Eigen::Vector2d ref = ch.com_position(th, 1);
  EXPECT_NEAR(tip.x(), ref.x(), 1e-5);
  EXPECT_NEAR(tip.z(), ref.y(), 1e-5);
  EXPECT_NEAR(tip.x(), -1.040766, 1e-5);
  EXPECT_NEAR(tip.z(), -1.707348, 1e-5);
}

TEST(LmfsimAnalytic, DriftWithAndWithoutStabilisation) {
  // docs/lmfsim.md §7, table (targets within a factor 3): rk4 h = 1e-3 over 10 s.
  struct Case { double dt, ab, max_C, drift; } cases[] = {{1e-3, 0, 3.3e-8, 1.9e-8}, {1e-3, 10, 1.4e-10, 6.7e-10},
                                                           {1e-2, 0, 3.3e-4, 1.9e-4}, {1e-2, 10, 1.4e-6, 4.2e-6}};
  double C_with = 0, C_without = 0;
  for (const Case& c : cases) {
    System sys(chaotic_double_pendulum(c.dt, c.ab));
    double maxC = 0, drift = 0;
    const double E0 = sys.energy(sys.initial_state()).E();
    run(sys, [&](double t, const Eigen::VectorXd& st) {
      maxC = std::max(maxC, sys.max_violation(t, st));
      drift = std::max(drift, std::abs(sys.energy(st).E() - E0) / sys.energy_scale());
    });
    EXPECT_LT(maxC, 3 * c.max_C) << "h " << c.dt << " ab " << c.ab;
    EXPECT_LT(drift, 3 * c.drift) << "h " << c.dt << " ab " << c.ab;
    if (c.dt == 1e-3) (c.ab > 0 ? C_with : C_without) = maxC;
  }
  EXPECT_LT(C_with, C_without / 10);
  EXPECT_NEAR(System(chaotic_double_pendulum(1e-3, 10)).energy_scale(), 39.24, 1e-12);
}

TEST(LmfsimAnalytic, BaumgarteDecayLaw) {
  // Particle 1.1 m from the pivot of a 1 m rod, moving perpendicular to it: C0 = 0.105,
  // Cdot0 = 0; with alpha = beta: C(t) = (C0 + (Cdot0 + beta C0) t) e^{-beta t}.
  Scene s;
  s.gravity = Vec3::Zero();
  s.bodies.push_back(particle("bob", Vec3(1.1, 0, 0)));
  s.bodies[0].vel = Vec3(0, 0, 0.3);
  s.constraints.push_back(distance("rod", kWorld, 0, 1));
  s.sim.t_end = 3;
  s.sim.alpha = s.sim.beta = 5;
  s.sim.max_violation = 1;
  System sys(s);
  const double C0 = 0.105, beta = 5;
  double worst = 0;
  run(sys, [&](double t, const Eigen::VectorXd& st) {
    const double C = 0.5 * (st.head<3>().squaredNorm() - 1);
    worst = std::max(worst, std::abs(C - (C0 + beta * C0 * t) * std::exp(-beta * t)));
  });
  EXPECT_LT(worst, 1e-9);
}

TEST(LmfsimAnalytic, ActivationIsGradualAndVelocityContinuous) {
  // Constraint switched on at t = 0.5 s while violated: from then on C follows the law
  // with C0, Cdot0 of the free flight, and the velocity does not jump.
  Scene s;
  s.gravity = Vec3::Zero();
  s.bodies.push_back(particle("bob", Vec3(1.1, 0, 0)));
  s.bodies[0].vel = Vec3(0, 0.3, 0);
  s.constraints.push_back(distance("rod", kWorld, 0, 1));
  s.constraints[0].active = false;
  s.events.push_back(Event{0.5, EventAction::activate, "rod", {}});
  s.sim.t_end = 3;
  s.sim.alpha = s.sim.beta = 5;
  s.sim.max_violation = 1;
  System sys(s);
  const Vec3 p0(1.1, 0.15, 0), v0(0, 0.3, 0);
  const double C0 = 0.5 * (p0.squaredNorm() - 1), Cd0 = p0.dot(v0), beta = 5;
  double worst = 0, jump = 0;
  Vec3 v_prev = v0;
  run(sys, [&](double t, const Eigen::VectorXd& st) {
    const Vec3 v = st.segment<3>(3);
    if (t > 0.5 - 1e-12 && t < 0.5 + 1e-12) jump = (v - v_prev).norm();
    v_prev = v;
    if (t < 0.5) return;
    const double tau = t - 0.5, C = 0.5 * (st.head<3>().squaredNorm() - 1);
    worst = std::max(worst, std::abs(C - (C0 + (Cd0 + beta * C0) * tau) * std::exp(-beta * tau)));
  });
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(jump, 1e-9);
}

TEST(LmfsimAnalytic, RodTensionFromMultiplier) {
  Scene s = particle_chain({kPi / 2});
  s.sim.t_end = 3;
  System sys(s);
  double worst = 0;
  Eigen::VectorXd ds;
  run(sys, [&](double t, const Eigen::VectorXd& st) {
    sys.derivative(t, st, ds);
    const Vec3 p = st.head<3>(), v = st.segment<3>(3);
    const double force = std::abs(sys.lambda()[0][0]) * p.norm();  // J_b^T lambda = d lambda
    const double expect = 1.0 * (9.81 * (-p.z()) + v.squaredNorm());
    if (expect > 1e-3) worst = std::max(worst, std::abs(force - expect) / expect);
  });
  EXPECT_LT(worst, 1e-6);
}

TEST(LmfsimAnalytic, FourBarFollowsItsOneDofEquation) {
  // Zero gravity: energy conservation of the 1-DOF system gives phidot = sqrt(2 E0 / M(phi)).
  FourBar fb;
  Scene s = fourbar(kPi / 2, 2.0, 0.0, fb);
  s.sim.t_end = 19;  // more than five crank turns
  System sys(s);
  const double E0 = 0.5 * fb.mass(kPi / 2) * 4.0;
  double worst = 0, maxC = 0, turned = 0, last = kPi / 2;
  run(sys, [&](double t, const Eigen::VectorXd& st) {
    const Vec3 dir = sys.orientation(0, st) * Vec3::UnitX();
    const double phi = std::atan2(dir.z(), dir.x());
    const double rate = -st[10];  // crank omega_y
    worst = std::max(worst, std::abs(rate - std::sqrt(2 * E0 / fb.mass(phi))) / rate);
    maxC = std::max(maxC, sys.max_violation(t, st));
    turned += std::remainder(phi - last, 2 * kPi);
    last = phi;
  });
  EXPECT_GT(turned, 5 * 2 * kPi);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(maxC, 1e-9);
}

TEST(LmfsimAnalytic, FourBarWithGravityMatchesReducedModel) {
  FourBar fb;
  Scene s = fourbar(kPi / 2, 2.0, 9.81, fb);
  s.sim.t_end = 2;
  // RK4 error in the crank angle: 1.3e-5 rad at h = 1e-3, fourth order, so h = 2.5e-4.
  s.sim.dt = 2.5e-4;
  System sys(s);
  double phi_sim = 0;
  run(sys, [&](double, const Eigen::VectorXd& st) {
    const Vec3 dir = sys.orientation(0, st) * Vec3::UnitX();
    phi_sim = std::atan2(dir.z(), dir.x());
  });
  double phi = kPi / 2, phid = 2;
  for (int k = 0; k < 20000; ++k) fb.step_rk4(phi, phid, 1e-4);
  EXPECT_LT(std::abs(std::remainder(phi_sim - phi, 2 * kPi)), 1e-6);
}

TEST(LmfsimAnalytic, MotorRateErrorDecaysFirstOrder) {
  Scene s;
  s.gravity = Vec3::Zero();
  s.bodies.push_back(box_body("arm", Vec3(0.5, 0, 0), Vec3(1, 0.05, 0.05), 1));
  s.constraints.push_back(hinge("h", kWorld, Vec3::Zero(), 0, Vec3(-0.5, 0, 0)));
  Constraint m;
  m.name = "motor";
  m.type = ConstraintType::motor;
  m.a = kWorld;
  m.b = 0;
  m.axis_a = Vec3::UnitY();
  m.omega.value = 2;
  s.constraints.push_back(m);
  s.sim.t_end = 1.5;
  s.sim.alpha = 10;
  System sys(s);
  double worst = 0, last = 1;
  run(sys, [&](double t, const Eigen::VectorXd& st) {
    const double err = st[11] - 2;  // omega_y - Omega
    worst = std::max(worst, std::abs(err - (-2 * std::exp(-2 * 10 * t))));
    last = err;
  });
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(std::abs(last), 1e-9);
}

TEST(LmfsimAnalytic, FreeRigidBodyKeepsEnergyAndMomentum) {
  Scene s;
  s.gravity = Vec3::Zero();
  s.bodies.push_back(box_body("b", Vec3::Zero(), Vec3(1, 0.5, 0.2), 2));
  s.bodies[0].omega = Vec3(1, 0.5, 1.2);
  s.sim.t_end = 10;
  s.sim.every = 100;
  System sys(s);
  const Eigen::VectorXd s0 = sys.initial_state();
  auto momentum = [&](const Eigen::VectorXd& st) {
    const BodyKin k = sys.kinematics(0, st);
    return Vec3(k.R * s.bodies[0].inertia * k.R.transpose() * k.w);
  };
  const double T0 = sys.energy(s0).T, L0 = momentum(s0).norm();
  double dT = 0, dL = 0;
  run(sys, [&](double, const Eigen::VectorXd& st) {
    dT = std::max(dT, std::abs(sys.energy(st).T - T0) / T0);
    dL = std::max(dL, std::abs(momentum(st).norm() - L0) / L0);
  });
  EXPECT_LT(dT, 1e-9);
  EXPECT_LT(dL, 1e-9);
}

TEST(LmfsimAnalytic, KnifeEdgeWithCentredMassRunsOnACircle) {
  // A body held on z = 0 (point_on_plane at the COM, body z parallel to world z) with a
  // blade along body x at the COM: v and omega stay constant, the path is a circle of
  // radius v / omega, and the contact point never slides sideways.
  Scene s;
  s.gravity = Vec3::Zero();
  s.bodies.push_back(box_body("sleigh", Vec3::Zero(), Vec3(0.6, 0.3, 0.1), 2));
  s.bodies[0].vel = Vec3(1, 0, 0);
  s.bodies[0].omega = Vec3(0, 0, 0.5);
  Constraint plane;
  plane.name = "plane";
  plane.type = ConstraintType::point_on_plane;
  plane.a = 0;
  plane.direction = Vec3::UnitZ();
  Constraint upright;
  upright.name = "upright";
  upright.type = ConstraintType::axis_parallel;
  upright.a = 0;
  upright.b = kWorld;
  upright.axis_a = Vec3::UnitZ();
  upright.axis_b = Vec3::UnitZ();
  Constraint blade;
  blade.name = "blade";
  blade.type = ConstraintType::knife_edge;
  blade.a = 0;
  blade.axis_a = Vec3::UnitY();  // blade normal in the body frame
  s.constraints = {plane, upright, blade};
  s.sim.t_end = 10;
  s.sim.every = 10;
  System sys(s);
  const Vec3 centre(0, 2, 0);  // radius v / omega = 2, turning left
  double radius_err = 0, lateral = 0, speed_err = 0;
  run(sys, [&](double, const Eigen::VectorXd& st) {
    const BodyKin k = sys.kinematics(0, st);
    radius_err = std::max(radius_err, std::abs((k.p - centre).norm() - 2));
    lateral = std::max(lateral, std::abs((k.R * Vec3::UnitY()).dot(k.v)));
    speed_err = std::max(speed_err, std::abs(k.v.norm() - 1) + std::abs(k.w.z() - 0.5));
  });
  EXPECT_LT(radius_err, 1e-7);
  EXPECT_LT(lateral, 1e-10);
  EXPECT_LT(speed_err, 1e-9);
}

TEST(LmfsimAnalytic, PenaltyConvergesToMultipliersAsStiffnessGrows) {
  // Chaotic double pendulum for 1 s: the penalty tip error against the LMF run shrinks
  // monotonically for kappa = 1, 10, 100 (h = 1e-5 keeps the stiff springs stable).
  Scene lmf = particle_chain({kPi / 2, kPi / 2});
  lmf.sim.t_end = 1;
  lmf.sim.dt = 1e-4;
  lmf.sim.every = 10000;
  Vec3 ref;
  {
    System sys(lmf);
    run(sys, [&](double, const Eigen::VectorXd& st) { ref = st.segment<3>(6); });
  }
  double last = 1e300;
  for (double kappa : {1.0, 10.0, 100.0}) {
    Scene pen = lmf;
    pen.sim.formulation = Formulation::penalty;
    pen.sim.kappa = kappa;
    pen.sim.dt = 1e-5;
    pen.sim.every = 100000;
    System sys(pen);
    Vec3 tip;
    run(sys, [&](double, const Eigen::VectorXd& st) { tip = st.segment<3>(6); });
    const double err = (tip - ref).norm();
    EXPECT_LT(err, last) << "kappa " << kappa;
    last = err;
  }
}

// |C| above the limit ends the run with the figures (the tool names its flag, lib does not).
TEST(LmfsimAnalytic, ViolationLimitCarriesTheFigures) {
  Scene s = particle_chain({kPi / 2});
  s.sim.t_end = 1;
  s.sim.dt = 1e-2;
  s.sim.integrator = Integrator::euler;
  s.sim.stab = Stabilization::none;
  s.sim.max_violation = 1e-9;
  System sys(std::move(s));
  try {
    simulate(sys, [](int, double, const Eigen::VectorXd&) {});
    ADD_FAILURE() << "explicit Euler without stabilisation kept |C| below 1e-9";
  } catch (const ViolationLimitExceeded& e) {
    EXPECT_EQ(e.status(), fest::Status::failure);
    EXPECT_EQ(e.limit, 1e-9);
    EXPECT_GT(e.violation, 1e-9);
    EXPECT_GT(e.t, 0.0);
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
}

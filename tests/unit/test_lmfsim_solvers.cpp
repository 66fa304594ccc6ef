// Baraff's O(n) solver against the dense reference on trees, loops and redundant sets
// (docs/lmfsim.md §3), and the KKT residual of both.
#include <gtest/gtest.h>

#include <random>

#include "lmfsim/system.hpp"
#include "lmfsim_scenes.hpp"

using namespace lmfsim_test;

namespace {

// Accelerations of both solvers at the initial state (with random velocities).
// Loops keep the scene's (consistent) velocities: their redundant rows are redundant only
// on the constraint manifold; trees get random velocities.
void compare(Scene scene, double tol, bool random_velocities = true) {
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (Body& b : scene.bodies) {
    if (!random_velocities) break;
    b.vel = Vec3(u(g), u(g), u(g));
    if (b.kind == BodyKind::rigid) b.omega = Vec3(u(g), u(g), u(g));
  }
  scene.sim.stab = Stabilization::none;
  Scene dense_scene = scene;
  dense_scene.sim.solver = SolverKind::dense;
  scene.sim.solver = SolverKind::baraff;
  System sb(scene), sd(dense_scene);
  const Eigen::VectorXd s0 = sb.initial_state();
  Eigen::VectorXd db, dd;
  sb.derivative(0.1, s0, db);
  sd.derivative(0.1, s0, dd);
  const double scale = 1 + dd.cwiseAbs().maxCoeff();
  EXPECT_LT((db - dd).cwiseAbs().maxCoeff() / scale, tol);
  // KKT residual: J xdd + c = 0 for both (with c from the constraint evaluation).
  Eigen::VectorXd C;
  const Eigen::MatrixXd J = sb.jacobian(0.1, s0, &C);
  // Velocity-level check on the acceleration: J xdd + c where c = -(J xdd) of the
  // dense answer; both must give the same J xdd.
  Eigen::VectorXd ab(J.cols()), ad(J.cols());
  int k = 0;
  for (Eigen::Index i = 0; i < s0.size(); ++i)
    if (sb.velocity_mask()[static_cast<std::size_t>(i)]) ab[k] = db[i], ad[k++] = dd[i];
  EXPECT_LT((J * ab - J * ad).cwiseAbs().maxCoeff() / scale, tol);
}

}  // namespace

TEST(LmfsimSolvers, AgreeOnParticleChain) { compare(particle_chain({1.0, 2.0, 0.5, 1.5, 0.2}), 1e-9); }

TEST(LmfsimSolvers, AgreeOnBoxChainWithBallsAndBranches) {
  Scene s;
  for (int i = 0; i < 6; ++i) s.bodies.push_back(box_body("b" + std::to_string(i), Vec3(i + 0.5, 0, 0), Vec3(1, 0.1, 0.2), 1 + i));
  Constraint c;
  c.type = ConstraintType::ball;
  c.a = kWorld, c.b = 0, c.pb = Vec3(-0.5, 0, 0), c.name = "j0";
  s.constraints.push_back(c);
  for (int i = 1; i < 6; ++i) {
    c.name = "j" + std::to_string(i);
    c.a = i == 4 ? 1 : i - 1;  // a branch at body 1
    c.pa = Vec3(0.5, 0, 0);
    c.b = i;
    c.pb = Vec3(-0.5, 0, 0);
    s.constraints.push_back(c);
  }
  compare(s, 1e-9);
}

TEST(LmfsimSolvers, AgreeOnFourBarLoopWithRedundantRows) {
  FourBar fb;
  Scene s = fourbar(1.2, 2.0, 9.81, fb);  // planar loop of hinges: 3 redundant rows
  compare(s, 1e-9, false);
}

TEST(LmfsimSolvers, AgreeOnDuplicatedHinge) {
  FourBar fb;
  Scene s = fourbar(0.4, 1.0, 9.81, fb);
  Constraint dup = s.constraints[1];
  dup.name = "h1bis";
  s.constraints.push_back(dup);
  compare(s, 1e-9, false);
}

TEST(LmfsimSolvers, DenseReportsRankDeficiencyOfRedundantLoop) {
  FourBar fb;
  Scene s = fourbar(0.4, 1.0, 9.81, fb);
  s.sim.solver = SolverKind::dense;
  System sys(s);
  Eigen::VectorXd ds;
  sys.derivative(0, sys.initial_state(), ds);
  // 20 rows on 18 dof with one mobility: rank 17, so 3 rows are redundant.
  EXPECT_EQ(sys.info().rank_deficiency, 3);
  s.sim.solver = SolverKind::baraff;
  System sb(s);
  sb.derivative(0, sb.initial_state(), ds);
  EXPECT_EQ(sb.info().rank_deficiency, 3);
}

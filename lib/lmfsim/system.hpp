#pragma once
// The mechanical system in maximal coordinates (docs/lmfsim.md §1, §3, §5, §6): state
// layout, forces, the constraint set with its stabilisation, and the derivative
// f(t, s) = (xdot, xdd) that the integrators call.
//
// State layout per moving body: particle p(3) v(3); rigid p(3) q(4: w x y z) v(3) w(3);
// then 3 integral terms per PID element.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lmfsim/constraint_eval.hpp"
#include "lmfsim/model.hpp"
#include "lmfsim/solver.hpp"

namespace fest::lmfsim {

// Figures of the latest derivative evaluation (docs/lmfsim.md).
struct EvalInfo {
  double C_max = 0, Cdot_max = 0, Cv_max = 0;  // active holonomic C, its rate, velocity rows
  int rows = 0;
  int rank_deficiency = 0;
  double residual = 0;
  double solve_us = 0;  // wall time of the constraint solve
};

struct Energy {
  double T = 0, U = 0;
  double E() const { return T + U; }
};

class System {
 public:
  explicit System(Scene scene);  // validates (bad_input)
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  const Scene& scene() const { return scene_; }
  const SimSettings& settings() const { return scene_.sim; }
  int state_size() const { return n_state_; }
  Eigen::VectorXd initial_state() const;

  // ds = f(t, s). Throws runtime_failure when the constraint rows are conflicting
  // (the truncated SVD cannot satisfy them).
  void derivative(double t, const Eigen::VectorXd& s, Eigen::VectorXd& ds);
  // Only the position rates (pdot, qdot, PID integrands) from the velocities in s.
  void kinematic_rate(double t, const Eigen::VectorXd& s, Eigen::VectorXd& ds) const;
  // true at indices that hold velocities (v, omega).
  const std::vector<bool>& velocity_mask() const { return vel_mask_; }
  // Renormalises quaternions (after each completed step).
  void normalize(Eigen::VectorXd& s) const;
  // Post-step projection of positions and velocities onto the constraints (stab project).
  void project(double t, Eigen::VectorXd& s);

  // Largest |C| over active holonomic rows at (t, s): no solve.
  double max_violation(double t, const Eigen::VectorXd& s) const;
  Energy energy(const Eigen::VectorXd& s) const;
  // The energy scale E_scale (docs/lmfsim.md §7) at the initial state.
  double energy_scale() const;
  double length_scale() const { return length_scale_; }
  bool conservative() const;

  const EvalInfo& info() const { return info_; }
  // Multipliers of the latest evaluation, one entry per constraint of the scene (empty
  // for inactive ones), and the constraint forces per body (force, torque about COM).
  const std::vector<Vecx>& lambda() const { return lambda_; }
  std::vector<Vec6> constraint_wrenches(double t, const Eigen::VectorXd& s) const;

  // Pose and velocity of scene body b in state s (fixed bodies: their scene pose).
  BodyKin kinematics(int b, const Eigen::VectorXd& s) const;
  Quat orientation(int b, const Eigen::VectorXd& s) const;

  // Events (docs/lmfsim.md §6). Throws bad_input for a target that does not exist.
  void check_event(const Event& e) const;
  void apply_event(const Event& e, Eigen::VectorXd& s);

  int constraint_index(const std::string& name) const;
  int force_index(const std::string& name) const;
  int body_index(const std::string& name) const;
  // Count of active scalar constraint rows and their Jacobian at s (for check).
  Eigen::MatrixXd jacobian(double t, const Eigen::VectorXd& s, Eigen::VectorXd* C = nullptr) const;
  int dof_total() const { return n_dof_; }

 private:
  void compute_kinematics(const Eigen::VectorXd& s, std::vector<BodyKin>& kin) const;
  void build_problem(double t, const Eigen::VectorXd& s);
  void collect_active();

  Scene scene_;
  std::vector<int> moving_;     // scene body -> moving index or -1
  std::vector<int> moving_body_;  // moving index -> scene body
  std::vector<int> offset_;     // moving index -> state offset
  std::vector<int> pid_offset_;  // force index -> state offset of its integral (or -1)
  std::vector<bool> vel_mask_;
  int n_state_ = 0, n_dof_ = 0;
  double length_scale_ = 1;
  double energy_scale_ = 1;

  std::unique_ptr<Solver> solver_;
  bool topology_changed_ = true;
  std::vector<int> active_;  // indices of active constraints
  // Workspace (allocated once, reused every evaluation).
  std::vector<Mat3> inertia_inv_;  // body-frame inverse inertia, per scene body
  std::vector<BodyKin> kin_;
  std::vector<SolveBody> bodies_;
  std::vector<ConstraintEval> evals_;
  std::vector<SolveConstraint> cons_;
  SolveResult result_;
  std::vector<Vecx> lambda_;
  EvalInfo info_;
};

}  // namespace fest::lmfsim

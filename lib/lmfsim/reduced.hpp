#pragma once
// Reduced-coordinate references (docs/lmfsim.md §5), planar in the x-z plane, gravity -g z:
//  * open chains of N links about parallel hinge axes, angles from the downward vertical;
//  * the four-bar linkage as a 1-DOF Lagrangian system in the crank angle.

#include <vector>

#include <Eigen/Core>

namespace fest::lmfsim {

struct ChainLink {
  double length = 1;
  double mass = 1;
  double com = 1;      // COM at this fraction of the link (1: point mass at the tip)
  double inertia = 0;  // about the COM, for rotation in the plane
};

struct ReducedChain {
  std::vector<ChainLink> links;
  double g = 9.81;
  // theta_dd from M theta_dd + h + G = 0.
  Eigen::VectorXd acceleration(const Eigen::VectorXd& th, const Eigen::VectorXd& thd) const;
  Eigen::MatrixXd mass_matrix(const Eigen::VectorXd& th) const;
  double energy(const Eigen::VectorXd& th, const Eigen::VectorXd& thd) const;
  // COM of link i (x, z) relative to the pivot.
  Eigen::Vector2d com_position(const Eigen::VectorXd& th, int i) const;
  Eigen::Vector2d com_velocity(const Eigen::VectorXd& th, const Eigen::VectorXd& thd, int i) const;
  // One classic RK4 step of (th, thd).
  void step_rk4(Eigen::VectorXd& th, Eigen::VectorXd& thd, double h) const;
};

// Four-bar: ground pivots O = (0, 0) and D = (d, 0); crank a (O-A), coupler b (A-B),
// rocker c (D-B); uniform rods of the given masses (or any COM inertia).
struct FourBar {
  double a = 0.3, b = 1, c = 0.8, d = 1;
  double m[3] = {0.3, 1, 0.8};   // crank, coupler, rocker
  double J[3] = {0, 0, 0};       // COM inertia per link (uniform rod: m l^2 / 12)
  double g = 9.81;
  int branch = 1;  // sign of cross(B - A, D - A): which circle intersection B is

  struct Pose {
    Eigen::Vector2d A, B;
    double angle[3];  // crank phi, coupler gamma, rocker psi (from +x toward +z)
    Eigen::Vector2d com[3];
  };
  // Throws runtime_failure where the loop cannot close (outside the Grashof range).
  Pose pose(double phi) const;
  // Generalised mass M(phi) = sum m |dx_c/dphi|^2 + J (dtheta/dphi)^2, potential V(phi).
  double mass(double phi) const;
  double potential(double phi) const;
  double acceleration(double phi, double phid) const;
  void step_rk4(double& phi, double& phid, double h) const;
  // Branch of a given assembled configuration.
  static int branch_of(const Eigen::Vector2d& A, const Eigen::Vector2d& B, const Eigen::Vector2d& D);
};

}  // namespace fest::lmfsim

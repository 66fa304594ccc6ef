#pragma once
// Time integration of the system's state (docs/lmfsim.md §6): explicit Euler, symplectic
// (semi-implicit) Euler, classic RK4 and Dormand-Prince 5(4) with error control.

#include <Eigen/Core>

#include "lmfsim/system.hpp"

namespace fest::lmfsim {

struct StepCounters {
  long steps = 0;   // accepted steps
  long evals = 0;   // derivative evaluations
  long rejected = 0;
};

// Advances s from t to t + h with one fixed step (euler, symplectic, rk4) or with as many
// adaptive Dormand-Prince steps as rtol/atol need (rk45; h_try keeps the last step size
// between calls). Quaternions are renormalised after each completed step.
void advance(System& sys, Integrator method, double t, double h, Eigen::VectorXd& s, StepCounters& counters,
             double& h_try);

}  // namespace fest::lmfsim

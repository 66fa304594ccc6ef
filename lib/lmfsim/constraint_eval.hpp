#pragma once
// Evaluation of one constraint at a state (docs/lmfsim.md §2): C (or C_v for velocity rows),
// dC/dt, the Jacobian blocks J_a, J_b (rows x 6, linear | angular) and c of the
// acceleration form J xdd + c = 0.

#include "lmfsim/kinematics.hpp"

namespace fest::lmfsim {

struct ConstraintEval {
  int rows = 0;
  Vecx C, Cdot, c;
  Blk Ja, Jb;  // rows x 6 each; angular columns are zero for particles
};

// ka / kb: kinematics of c.a / c.b (the world's for kWorld). t: time.
void eval_constraint(const Constraint& c, const BodyKin& ka, const BodyKin& kb, double t, ConstraintEval& out);

}  // namespace fest::lmfsim

#pragma once
// Where and when the path leaves the cell (spec §2.5): the smallest tau > 0 at which a
// barycentric coordinate beta_k(x(tau)) reaches 0 from above.
//
// bracket (default): sample the closed form at growing steps until some beta_k < 0, then
//   safeguarded Newton inside the first bracket (Newton step when it stays inside,
//   bisection otherwise). It cannot converge to a negative or later root.
// Before the bracket search, a predicted exit (Taylor cubic of beta_k from the entry,
//   one evaluation, Halley correction) is tried and kept when it passes the bracket
//   search's safety checks; see predicted_exit() in exit_search.cpp.
// newton (the paper's, §9.3.4): Newton from tau = 0 on each face; the smallest positive
//   root that validates (all beta >= 0 at tau*/4, tau*/2, 3tau*/4 and tau*) is taken,
//   otherwise the bracket search runs.

#include "lemtrace/closed_form.hpp"

namespace fest::lemtrace {

struct ExitParams {
  bool paper_newton = false;
  double eps_newton = 1e-12;  // relative to tau_T
  int max_samples = 4096;
  bool predict = true;        // try the Taylor-predicted exit (one evaluation) first
};

struct ExitResult {
  enum Kind { exit, trapped, stalled } kind = trapped;
  double tau = 0;                 // exit time, or the time reached when trapped/stalled
  int face = -1;                  // local face (opposite vertex) left through
  Vec3 x = Vec3::Zero();          // exit point snapped onto the face
  Eigen::Vector4d beta = Eigen::Vector4d::Zero();
  int evaluations = 0;            // closed-form evaluations (cost measure, Table 9.3)
};

// What the caller already knows at the entry point (barycentric coordinates and the
// interpolated field there), so that the search does not compute it again.
struct EntryValues {
  Eigen::Vector4d beta;
  Vec3 field;
};

ExitResult find_exit(const TetGeometry& g, const CellPath& path, const ExitParams& params,
                     const EntryValues* entry = nullptr);

}  // namespace fest::lemtrace

#pragma once
// Where and when the path leaves the cell (docs/lemtrace.md §3): the smallest tau > 0 at which a
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

// The cell in its own barycentric coordinates u = (beta_1, beta_2, beta_3): vertices at
// 0, e1, e2, e3, so beta = (1 - sum u, u) with no matrix product. Paths of records in the
// barycentric frame (to_barycentric_frame) are searched here; positions are u.
struct UnitGeometry {
  double h_min = 1;  // the edges from vertex 0; the others are sqrt 2
  double v_max = 0;  // largest vertex speed in u, 1 / tau_bary
  explicit UnitGeometry(double tau_bary) : v_max(1.0 / tau_bary) {}
  Eigen::Vector4d bary(const Vec3& u) const { return {1.0 - u.sum(), u[0], u[1], u[2]}; }
  Eigen::Vector4d bary_rate(const Vec3& w) const { return {-w.sum(), w[0], w[1], w[2]}; }
  Vec3 point(const Eigen::Vector4d& beta) const { return {beta[1], beta[2], beta[3]}; }
  double transit_time() const;
};

ExitResult find_exit(const TetGeometry& g, const CellPath& path, const ExitParams& params,
                     const EntryValues* entry = nullptr);
// The same search in the barycentric frame (x, beta and tau as above, x = u).
ExitResult find_exit(const UnitGeometry& g, const CellPath& path, const ExitParams& params,
                     const EntryValues* entry = nullptr);

// The predicted exit (the bracket search's fast path) of a normal cell whose record is in
// the barycentric frame, done entirely in eigen coordinates: z0 = S_u^{-1} u0, every time
// derivative is a product with Lambda, and each barycentric coordinate is one row of S_u
// applied to z (beta_0 = 1 - the sum), so one crossing costs one change of basis in,
// one closed-form evaluation (no matrix product) and one change of basis out. The rules
// are those of the general search's prediction, except that a face grazed between entry
// and exit is kept when a rigorous lower bound of its beta over the step stays >= 0;
// false when the general search must decide (the caller then runs find_exit on a
// UnitGeometry). `beta` is the entry point, out.x is u.
bool predicted_exit_local(const CellRecord& rec, const Eigen::Vector4d& beta, double dir, ExitResult& out);

}  // namespace fest::lemtrace

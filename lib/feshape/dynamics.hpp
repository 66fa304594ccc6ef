#pragma once
// The seed's own solver (App. C eq. 6, docs/feshape.md §1.5): massless first-order
// dynamics D q' + K q = f_q integrated by explicit Euler, with the generalized forces of
// eqs. 4-5 and 10-11 gathered at the nodes; optionally semi-implicit in K for q_d.

#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "feshape/closest.hpp"
#include "feshape/model.hpp"

namespace fest::feshape {

struct Damping {
  double c = 1, theta = 1, s = 1, d = 1;  // diagonal of D per block
};

class EulerIntegrator {
 public:
  // `local`: whether q_d moves (false in the global phase). `semi_implicit`:
  // (D + dt K) q_d+ = D q_d + dt f_d, factored once here.
  EulerIntegrator(const Eigen::SparseMatrix<double>& k, double beta, double dt, const Damping& damping, bool local,
                  bool semi_implicit);
  ~EulerIntegrator();
  // One step with the given assignment. Fails (Status::failure) on a non-finite state.
  void step(Model& m, const std::vector<Eigen::Vector3d>& points, const std::vector<MeshPoint>& assigned) const;

 private:
  struct Factor;
  const Eigen::SparseMatrix<double>& k_;
  double beta_, dt_;
  Damping damping_;
  bool local_;
  std::unique_ptr<Factor> factor_;
};

}  // namespace fest::feshape

// lmfsim check: topology, rank and degrees of freedom of the scene, as JSON.
#include <functional>
#include <set>

#include <Eigen/SVD>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/solver.hpp"
#include "lmfsim/system.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

int cmd_check(const SimOverrides& over) {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  Scene scene = load_scene(scene_bytes);
  over.apply(scene.sim);
  System sys(std::move(scene));
  const Scene& sc = sys.scene();
  const Eigen::VectorXd s0 = sys.initial_state();
  Eigen::VectorXd C;
  const Eigen::MatrixXd J = sys.jacobian(0, s0, &C);
  int rank = 0;
  if (J.rows() > 0) {
    // Singular values only, by divide and conquer: the rank needs no U or V, and BDCSVD's
    // bidiagonalisation is O(m n^2) where one-sided Jacobi sweeps the whole matrix many
    // times (a 500-link chain, J 1500 x 3000: 23 s with JacobiSVD at load ~4 on 2 cores).
    Eigen::BDCSVD<Eigen::MatrixXd> svd(J);
    const auto& sv = svd.singularValues();
    for (Eigen::Index i = 0; i < sv.size(); ++i)
      if (sv[i] > sc.sim.svd_tol * sv[0]) ++rank;
  }
  // Topology: primary (spanning forest) versus auxiliary rows, components.
  std::vector<SolveConstraint> cons;
  std::vector<int> moving(sc.bodies.size(), -1);
  int nm = 0;
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    if (!sc.bodies[i].fixed) moving[i] = nm++;
  std::vector<const Constraint*> active;
  for (const Constraint& c : sc.constraints) {
    if (!c.active) continue;
    SolveConstraint s;
    s.a = c.a < 0 ? -1 : moving[static_cast<std::size_t>(c.a)];
    s.b = c.b < 0 ? -1 : moving[static_cast<std::size_t>(c.b)];
    s.c.setZero(constraint_rows(c.type));
    cons.push_back(s);
    active.push_back(&c);
  }
  const std::vector<bool> primary = primary_constraints(nm, cons);
  int prim_rows = 0, aux_rows = 0;
  nlohmann::json aux = nlohmann::json::array();
  for (std::size_t j = 0; j < cons.size(); ++j) {
    if (primary[j]) prim_rows += cons[j].rows();
    else {
      aux_rows += cons[j].rows();
      aux.push_back(active[j]->name);
    }
  }
  // Components of the body graph without the ground (a free body is one).
  std::vector<int> comp(static_cast<std::size_t>(nm));
  for (int i = 0; i < nm; ++i) comp[static_cast<std::size_t>(i)] = i;
  std::function<int(int)> find = [&](int i) { return comp[static_cast<std::size_t>(i)] == i ? i : comp[static_cast<std::size_t>(i)] = find(comp[static_cast<std::size_t>(i)]); };
  for (const auto& s : cons)
    if (s.a >= 0 && s.b >= 0) comp[static_cast<std::size_t>(find(s.a))] = find(s.b);
  std::set<int> roots;
  for (int i = 0; i < nm; ++i) roots.insert(find(i));
  const double h = sc.sim.dt, beta = sc.sim.beta;
  const bool euler = sc.sim.integrator == Integrator::euler || sc.sim.integrator == Integrator::symplectic;
  const double limit = euler ? 0.05 : 0.2;
  nlohmann::json rep = {{"bodies", sc.bodies.size()},
                        {"moving_bodies", nm},
                        {"dof_unconstrained", sys.dof_total()},
                        {"constraints", sc.constraints.size()},
                        {"active_rows", J.rows()},
                        {"components", roots.size()},
                        {"primary_rows", prim_rows},
                        {"auxiliary_rows", aux_rows},
                        {"auxiliary_constraints", aux},
                        {"rank_J", rank},
                        {"rank_deficiency", static_cast<int>(J.rows()) - rank},
                        {"dof", sys.dof_total() - rank},
                        {"initial_C_max", C.size() ? C.cwiseAbs().maxCoeff() : 0.0},
                        {"length_scale", sys.length_scale()},
                        {"beta_h", beta * h},
                        {"beta_h_limit", limit},
                        {"stabilisation_ok", sc.sim.stab != Stabilization::baumgarte || beta * h <= limit}};
  fest::write_output("-", fest::formats::write_json(rep));
  return 0;
}

}  // namespace fest::lmfsim_tool

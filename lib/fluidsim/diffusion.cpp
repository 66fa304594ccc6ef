#include "fluidsim/diffusion.hpp"

#include <map>

namespace fest::fluidsim {

namespace {

std::vector<int> diffusion_nodes(const Layout& L, int axis, Parity parity) {
  std::vector<int> nodes;
  const bool dirichlet = L.closed(axis) && parity == Parity::odd;
  for (int i = dirichlet ? 1 : 0; i < (dirichlet ? L.size[axis] - 1 : L.size[axis]); ++i) nodes.push_back(i);
  return nodes;
}

}  // namespace

Diffuser::Diffuser(const Layout& layout, double coefficient, Transform kind, bool no_slip)
    : layout_(layout), coefficient_(coefficient) {
  std::map<std::pair<int, int>, std::shared_ptr<const AxisBasis>> bases;
  auto basis = [&](int axis, Parity p) {
    const auto key = std::make_pair(axis, static_cast<int>(p));
    auto it = bases.find(key);
    if (it != bases.end()) return it->second;
    auto b = std::make_shared<const AxisBasis>(layout_, axis, diffusion_nodes(layout_, axis, p), 1, p, kind);
    bases.emplace(key, b);
    return std::shared_ptr<const AxisBasis>(b);
  };
  for (int c = 0; c < layout_.dim; ++c) {
    std::array<std::shared_ptr<const AxisBasis>, 3> axes;
    for (int a = 0; a < 3; ++a)
      axes[a] = basis(a, layout_.active(a) ? velocity_parity(c, a, no_slip) : Parity::even);
    velocity_[c] = std::make_unique<BoxSolver>(axes, 1.0, -coefficient_);
  }
  std::array<std::shared_ptr<const AxisBasis>, 3> axes{basis(0, Parity::even), basis(1, Parity::even),
                                                       basis(2, Parity::even)};
  scalar_ = std::make_unique<BoxSolver>(axes, 1.0, -coefficient_);
}

Diffuser::~Diffuser() = default;

// In place: the solve gathers its whole box before it writes, and the nodes outside the
// box (the walls of an odd field) keep their values.
void Diffuser::velocity(int component, Field& f) const { velocity_[component]->solve(layout_, f, f, &buffers_); }

void Diffuser::velocity(Velocity& u) const {
  std::vector<BoxJob> jobs;
  for (int c = 0; c < layout_.dim; ++c) jobs.push_back({velocity_[c].get(), &u[c], &u[c]});
  BoxSolver::solve_all(layout_, jobs, &buffers_);
}

void Diffuser::scalar(Field& f) const { scalar_->solve(layout_, f, f, &buffers_); }

}  // namespace fest::fluidsim

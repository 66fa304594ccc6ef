#pragma once
// One simulation step of the chapter (specs/fluidsim.md 2.2-2.3): velocity
// force -> advect -> diffuse -> project, scalars source -> advect -> diffuse -> dissipate.
// The scalar step to level n+1 uses the velocity of level n and the vector step uses the
// scalars of level n (buoyancy), so the two are independent of each other.

#include <memory>
#include <string>
#include <vector>

#include "fluidsim/diffusion.hpp"
#include "fluidsim/grid.hpp"
#include "fluidsim/projection.hpp"
#include "fluidsim/scene.hpp"

namespace fest::fluidsim {

struct State {
  Velocity u;
  std::vector<Field> s;
  double t = 0.0;
  std::uint64_t step = 0;
};

struct SimOptions {
  ProjectionOptions projection;
  bool stam03 = false;       // Stam 2003 order: force, diffuse, project, advect, project
  bool mass_correct = false; // rescale scalars after advection to keep their weighted sum
};

struct StepStats {
  double ms_force = 0, ms_advect = 0, ms_diffuse = 0, ms_project = 0, ms_scalars = 0;
  ProjectionStats projection;
};

class Simulator {
 public:
  Simulator(const Scene& scene, const SimOptions& options);
  ~Simulator();

  const Layout& layout() const noexcept { return layout_; }
  const Scene& scene() const noexcept { return scene_; }
  State initial_state() const;
  // Advances the state by dt. Throws Status::failure when the state becomes non-finite.
  StepStats step(State& state, double dt) const;

 private:
  void add_forces(const State& state, double dt, Velocity& u) const;
  void scalar_step(const State& state, double dt, std::vector<Field>& out) const;
  const Diffuser* diffuser(double coefficient) const;  // nu dt or kappa dt

  Scene scene_;
  SimOptions options_;
  Layout layout_;
  std::unique_ptr<Projector> projector_;
  mutable std::vector<std::unique_ptr<Diffuser>> diffusers_;  // cached per (coefficient)
};

// Linear blend (1 - a) x + a y of every field: the interpolated frames of 2.7.
State blend(const State& x, const State& y, double a);

// Maximum speed over the nodes (domain units per second).
double max_speed(const Layout& layout, const Velocity& u);

// The analytic initial fields (domain [0, 2 pi) on periodic grids).
void taylor_green(const Layout& layout, Velocity& u);
void abc_flow(const Layout& layout, Velocity& u);

}  // namespace fest::fluidsim

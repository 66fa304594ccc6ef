#pragma once
// One simulation step of the chapter (docs/fluidsim.md §2): velocity
// force -> advect -> diffuse -> project, scalars source -> advect -> diffuse -> dissipate.
// Velocity and scalars are advected along the same back-traced characteristics of
// w1 = u^n + dt f(s^n), which depends on level n only, so one RK4 trace per node serves
// all 3 + S fields (the cost model of docs/fluidsim.md §7).

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
  // The scene's initial state; `given` (fields read from an init file by the caller, on
  // the stored grid) replaces the analytic ones. Throws Status::bad_input when its sizes
  // differ from the grid or it holds non-finite values. The velocity is projected.
  State initial_state(const State* given = nullptr) const;
  // Advances the state by dt. Throws Status::failure when the state becomes non-finite.
  StepStats step(State& state, double dt) const;

 private:
  void add_forces(const State& state, double dt, Velocity& u) const;
  // s + dt S (sources active at the state's time), into `src` (its buffers reused).
  void scalar_sources(const State& state, double dt, std::vector<Field>& src) const;
  // After advection: optional mass correction, implicit diffusion, dissipation.
  void finish_scalars(const std::vector<Field>& before, std::vector<Field>& s, double dt) const;
  const Diffuser* diffuser(double coefficient) const;  // nu dt or kappa dt

  Scene scene_;
  SimOptions options_;
  Layout layout_;
  std::unique_ptr<Projector> projector_;
  mutable std::vector<std::unique_ptr<Diffuser>> diffusers_;  // cached per (coefficient)
  // Buffers a step hands to the next (step() is not reentrant, like the diffuser cache):
  // the copy of the velocity, the advected velocity, the scalars with their sources and
  // the advected scalars. Fresh vectors were zero-filled or copied by one thread, a serial
  // part of every step that would cap the speed-up on many cores (docs/fluidsim.md §6).
  mutable Velocity spare_u_[2];
  mutable std::vector<Field> spare_s_[2];
};

// Linear blend (1 - a) x + a y of every field: the interpolated frames of 2.7.
State blend(const State& x, const State& y, double a);
// The same into `out`, whose buffers are reused when their sizes fit (a frame loop keeps
// one: a fresh State is zero-filled by one thread first).
void blend(const State& x, const State& y, double a, State& out);

// Maximum speed over the nodes (domain units per second).
double max_speed(const Layout& layout, const Velocity& u);

// The analytic initial fields (domain [0, 2 pi) on periodic grids).
void taylor_green(const Layout& layout, Velocity& u);
void abc_flow(const Layout& layout, Velocity& u);

}  // namespace fest::fluidsim

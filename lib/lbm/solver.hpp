#pragma once
// The lattice-Boltzmann solver (docs/lbmsim.md 2.2-2.4): D2Q9 or D3Q19, BGK or TRT with
// Guo forcing, fused pull stream-collide on two structure-of-arrays lattices, halfway
// bounce-back and Ladd moving walls per link, non-equilibrium extrapolation inlets and
// outlets, periodic faces, and a slab of a distributed lattice behind SlabExchange.
//
// The arrays hold post-collision populations f*(x, t); one step gathers f*(x - c_i, t)
// (bouncing back at walls), collides and writes f*(x, t+1). No I/O, no MPI.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "lbm/case.hpp"
#include "lbm/exchange.hpp"
#include "lbm/geometry.hpp"

namespace fest::lbm {

enum class Precision { f64, f32 };

// Initial state at an interior node (global coordinates): density and velocity.
using InitFunction = std::function<void(int x, int y, int z, double& rho, std::array<double, 3>& u)>;

struct SolverSetup {
  const Case* c = nullptr;
  const Flags* flags = nullptr;
  Precision precision = Precision::f64;
  SlabExchange* exchange = nullptr;  // nullptr: one process
  int slab_lo = 0, slab_hi = -1;     // layers of the last axis held here (-1: all)
  InitFunction init;                 // empty: the case's uniform init
};

class Solver {
 public:
  virtual ~Solver() = default;
  // One time step (with halo exchange when distributed).
  virtual void step() = 0;
  virtual long step_count() const = 0;
  // Density and velocity (3 components interleaved) of the local interior nodes at the
  // current time, x fastest (u includes F/2: the Guo velocity).
  // Solid nodes: rho = 1 (the reference), u = 0.
  virtual void moments(std::vector<double>& rho, std::vector<double>& u) const = 0;
  // Per local layer of the last axis: the sum of the fluid nodes' density, in node order.
  virtual std::vector<double> layer_mass() const = 0;
  // Per local layer: the force (3 components) on the solid nodes with this flag id, by
  // momentum exchange over the links into them (Ladd 1994), in link order.
  virtual std::vector<double> layer_force(std::uint8_t id) const = 0;
  // Lattice layout: local interior size and first global layer of the slab.
  virtual std::array<int, 3> local_size() const = 0;
  virtual int slab_lo() const = 0;
  virtual std::size_t fluid_nodes() const = 0;  // local
  // Bytes per lattice update of the two-lattice pull (read Q, write Q, write-allocate Q).
  virtual double bytes_per_update() const = 0;
  // Post-collision populations of the local interior nodes, [i][node] (tests).
  virtual std::vector<double> populations() const = 0;
};

std::unique_ptr<Solver> make_solver(const SolverSetup& setup);

// Relaxation rates: omega+ = 1/tau; TRT omega- from the magic parameter
// Lambda = (1/omega+ - 1/2)(1/omega- - 1/2) (Ginzburg et al. 2008); BGK: omega- = omega+.
std::array<double, 2> relaxation_rates(const Collision& c);

}  // namespace fest::lbm

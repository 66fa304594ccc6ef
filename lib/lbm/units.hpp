#pragma once
// The unit table of a case (docs/lbmsim.md 2.6): lattice and physical scales,
// dimensionless numbers, memory and a speed estimate.

#include <nlohmann/json_fwd.hpp>

#include "lbm/case.hpp"

namespace fest::lbm {

struct UnitTable {
  double dx = 1, dt = 1;            // metres and seconds per lattice unit (1 in lattice units)
  double nu = 0, tau = 0;           // lattice viscosity and relaxation time
  double omega_p = 0, omega_m = 0;
  double u_ref = 0, l_ref = 0;      // lattice
  double re = 0, ma = 0;
  double steps_per_second_phys = 0; // steps per physical second (physical units only)
  double force_scale = 1, pressure_scale = 1;  // lattice -> physical (N, Pa; per metre in 2-D)
  double memory_bytes = 0;          // populations (two lattices) + flags
  double mlups_estimate = 0;        // single-thread estimate from the memory traffic
  double steps_per_second = 0;      // wall-clock estimate
};

// `bandwidth` in bytes/s (a memory-copy figure; 0: 20 GB/s, a typical single core).
UnitTable unit_table(const Case& c, bool float32, double bandwidth = 0);
nlohmann::json unit_table_json(const UnitTable& t, const Case& c);

}  // namespace fest::lbm

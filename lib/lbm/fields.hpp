#pragma once
// Derived output fields (docs/lbmsim.md 2.7): density, pressure deviation, velocity,
// speed, vorticity (central differences, one-sided next to solids, 0 inside them),
// vorticity magnitude, Q-criterion (Hunt et al. 1988) and the solid flags.

#include <array>
#include <string>
#include <vector>

#include "lbm/case.hpp"
#include "lbm/geometry.hpp"

namespace fest::lbm {

struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components interleaved, x fastest
};

// Names accepted by derived_fields, in the order they are written.
const std::vector<std::string>& field_names();

// Checks a field list; throws Status::bad_input naming an unknown field ("did you mean").
void check_field_names(const std::vector<std::string>& names, const std::string& where);

// rho and u (3 components) of the whole lattice. Pressure is (rho - 1)/3 times
// `pressure_scale` (1 in lattice units); derivatives are per `spacing` (dx). 2-D
// vorticity is the scalar omega_z.
std::vector<Field> derived_fields(const std::vector<std::string>& names, const Case& c, const Flags& flags,
                                  const std::vector<double>& rho, const std::vector<double>& u,
                                  double pressure_scale = 1.0, double spacing = 1.0);

}  // namespace fest::lbm

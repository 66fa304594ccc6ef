// Unit conversion and the figures of `lbmsim info` (docs/lbmsim.md 2.6).
#include "lbm/units.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "lbm/solver.hpp"

namespace fest::lbm {

UnitTable unit_table(const Case& c, bool float32, double bandwidth) {
  UnitTable t;
  t.tau = c.collision.tau;
  t.nu = c.nu();
  const auto rates = relaxation_rates(c.collision);
  t.omega_p = rates[0];
  t.omega_m = rates[1];
  t.u_ref = c.u_ref;
  t.l_ref = c.lref();
  t.re = t.u_ref * t.l_ref / t.nu;
  t.ma = t.u_ref * std::sqrt(3.0);
  if (c.units.physical) {
    t.dx = c.units.dx;
    t.dt = c.units.dt();
    t.steps_per_second_phys = 1.0 / t.dt;
    const double rho = c.units.rho_phys;
    t.force_scale = rho * std::pow(t.dx, c.dim == 3 ? 4 : 3) / (t.dt * t.dt);
    t.pressure_scale = rho * t.dx * t.dx / (t.dt * t.dt);
  }
  const int Q = c.lattice == LatticeKind::d2q9 ? 9 : 19;
  const double real = float32 ? 4.0 : 8.0;
  t.memory_bytes = static_cast<double>(c.cells()) * (2.0 * Q * real + 1.0);
  const double bw = bandwidth > 0 ? bandwidth : 20e9;
  t.mlups_estimate = bw / (3.0 * Q * real) / 1e6 * 0.35;  // measured kernels reach about a third of the roofline
  t.steps_per_second = t.mlups_estimate * 1e6 / static_cast<double>(c.cells());
  return t;
}

nlohmann::json unit_table_json(const UnitTable& t, const Case& c) {
  nlohmann::json j = {{"lattice", c.lattice == LatticeKind::d2q9 ? "d2q9" : "d3q19"},
                      {"size", std::vector<int>(c.size.begin(), c.size.begin() + c.dim)},
                      {"collision", c.collision.model == CollisionModel::bgk ? "bgk" : "trt"},
                      {"tau", t.tau},
                      {"omega_plus", t.omega_p},
                      {"omega_minus", t.omega_m},
                      {"nu_lattice", t.nu},
                      {"u_ref_lattice", t.u_ref},
                      {"l_ref_lattice", t.l_ref},
                      {"re", t.re},
                      {"mach", t.ma},
                      {"physical_units", c.units.physical},
                      {"dx", t.dx},
                      {"dt", t.dt},
                      {"memory_bytes", t.memory_bytes},
                      {"mlups_estimate", t.mlups_estimate},
                      {"steps_per_second_estimate", t.steps_per_second}};
  j["equilibrium"] = c.collision.incompressible ? "incompressible" : "compressible";
  j["curved_walls"] = c.bouzidi ? "bouzidi" : "halfway";
  if (c.units.physical) {
    j["steps_per_physical_second"] = t.steps_per_second_phys;
    j["force_scale"] = t.force_scale;
    j["pressure_scale"] = t.pressure_scale;
    j["nu_phys"] = c.units.nu_phys;
    j["u_phys"] = c.units.u_phys;
  }
  return j;
}

}  // namespace fest::lbm

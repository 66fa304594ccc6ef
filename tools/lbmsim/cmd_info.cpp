// lbmsim info: the unit table of a case (docs/lbmsim.md 2.6).
#include <cstdio>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "case_loader.hpp"
#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "lbm/units.hpp"

namespace fest::lbmsim_tool {

int info_command(const InfoOptions& o) {
  const LoadedCase L = load_case(o.case_file, o.set);
  const lbm::Case& c = L.c;
  for (const std::string& w : c.warnings) warn("lbmsim", w);
  const lbm::UnitTable t = lbm::unit_table(c, o.precision == lbm::Precision::f32);
  if (o.json) {
    write_output("-", lbm::unit_table_json(t, c).dump(2) + "\n");
    return 0;
  }
  std::size_t solid = 0;
  for (auto v : L.flags.id) solid += v != 0;
  std::string s;
  s += fmt::format("lattice        {} {}{}{} ({} cells, {} solid)\n", c.lattice == lbm::LatticeKind::d2q9 ? "d2q9" : "d3q19",
                   c.size[0], fmt::format("x{}", c.size[1]), c.dim == 3 ? fmt::format("x{}", c.size[2]) : "", c.cells(), solid);
  s += fmt::format("collision      {}  tau {:.6g}  omega+ {:.6g}  omega- {:.6g}{}\n",
                   c.collision.model == lbm::CollisionModel::bgk ? "bgk" : "trt", t.tau, t.omega_p, t.omega_m,
                   c.collision.incompressible ? "  incompressible equilibrium" : "");
  if (c.bouzidi) s += "walls          interpolated bounce-back (Bouzidi) on spheres and cylinders\n";
  s += fmt::format("viscosity      {:.6g} (lattice)\n", t.nu);
  s += fmt::format("reference      u_ref {:.6g}  l_ref {:.6g} (lattice)\n", t.u_ref, t.l_ref);
  s += fmt::format("Re             {:.6g}\n", t.re);
  s += fmt::format("Ma             {:.4g}  (u_ref sqrt(3))\n", t.ma);
  if (c.units.physical) {
    s += fmt::format("dx             {:.6g} m\n", t.dx);
    s += fmt::format("dt             {:.6g} s  ({:.6g} steps per physical second)\n", t.dt, t.steps_per_second_phys);
    s += fmt::format("u_phys         {:.6g} m/s  <-> u_lattice {:.6g}\n", c.units.u_phys, c.units.u_lattice);
    s += fmt::format("nu_phys        {:.6g} m^2/s\n", c.units.nu_phys);
    s += fmt::format("force scale    {:.6g} N per lattice unit{}\n", t.force_scale, c.dim == 2 ? " (per metre of depth)" : "");
    s += fmt::format("pressure scale {:.6g} Pa per lattice unit\n", t.pressure_scale);
    s += fmt::format("physical time  {:.6g} s for {} steps\n", t.dt * c.steps, c.steps);
  } else {
    s += "units          lattice (dx = dt = 1)\n";
  }
  s += fmt::format("steps          {}{}\n", c.steady ? std::string("steady, tol ") + fmt::format("{:g}", c.tol) : std::to_string(c.steps), "");
  s += fmt::format("memory         {:.1f} MiB ({} precision, two lattices + flags)\n", t.memory_bytes / 1048576.0, precision_name(o.precision));
  s += fmt::format("speed estimate {:.3g} MLUPS per core, {:.3g} steps/s\n", t.mlups_estimate, t.steps_per_second);
  write_output("-", s);
  return 0;
}

}  // namespace fest::lbmsim_tool

#pragma once
// The scene description of fluidsim (fluidsim(1)), parsed from JSON with
// validation: unknown keys are errors with a "did you mean" hint, values are checked for
// range and finiteness. Positions are in node indices of the stored grid (closed axes:
// 0 and n+1 are the walls), velocities in domain units per second.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fluidsim/grid.hpp"

namespace fest::fluidsim {

struct Source {
  enum class Shape { box, sphere, gauss } shape = Shape::box;
  std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};  // box, inclusive
  std::array<double, 3> centre{0, 0, 0};             // sphere, gauss
  double radius = 1.0;                               // sphere radius, gauss sigma
  double rate = 0.0;                                 // scalar units per second
  bool jet = false;                                  // set the velocity inside every step
  std::array<double, 3> velocity{0, 0, 0};
  double start = 0.0, end = std::numeric_limits<double>::infinity();
};

struct ScalarSpec {
  std::string name = "density";
  double kappa = 0.0;
  double alpha = 0.0;
  double init = 0.0;  // uniform initial value
  std::vector<Source> sources;
};

struct Force {
  enum class Type { buoyancy, gravity, constant, vortex } type = Type::constant;
  std::string scalar;                 // buoyancy: f = beta (s - ambient) up
  double beta = 0.0, ambient = 0.0;
  std::array<double, 3> up{0, 0, 1};
  std::array<double, 3> value{0, 0, 0};  // gravity, constant
  std::array<double, 3> centre{0, 0, 0}; // vortex: swirl about `up` through centre
  double strength = 0.0, radius = 1.0;
};

struct InitSpec {
  std::string kind = "zero";  // zero | taylor-green | abc | noise | file
  std::string file;           // kind "file": a .vti or .nrrd frame, read by the tool
  unsigned seed = 1;
  double amp = 1.0;
};

struct Scene {
  int dim = 3;
  std::array<int, 3> dims{1, 1, 1};
  std::array<Boundary, 3> bc{Boundary::closed, Boundary::closed, Boundary::closed};
  double h = 0.0;  // 0: the default (domain length 1 along the longest axis)
  bool no_slip = false;
  double frame_dt = 0.04;
  int interp = 1;
  int frames = 100;
  double viscosity = 0.0;
  int substeps = 1;
  std::vector<ScalarSpec> scalars;
  std::vector<Force> forces;
  InitSpec init;
  std::vector<std::string> warnings;  // for the tool to print (partly clipped sources, ...)

  Layout layout() const;
};

// Parses and validates; `where` names the input in messages ("scene.json"). Throws
// Status::bad_input: `scene key "viscocity" is unknown (did you mean "viscosity"?) (scene.json)`.
Scene parse_scene(const nlohmann::json& doc, const std::string& where);

// A plume: one scalar ("density") fed by `source` and lifted by buoyancy (beta 1), the
// scenes of the interpolation check and of the stage benchmark.
void add_plume(Scene& scene, const Source& source);

}  // namespace fest::fluidsim

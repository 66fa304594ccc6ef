#pragma once
// The case model of lbmsim (docs/lbmsim.md "Case file"): lattice, collision, faces,
// geometry, initial state, output and monitors, in lattice units after unit conversion.
// Parsed from JSON by case_json.hpp; geometry files named here are read by the tool.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "lbm/lattice.hpp"

namespace fest::lbm {

enum class CollisionModel { bgk, trt };

struct Collision {
  CollisionModel model = CollisionModel::bgk;
  double tau = 0.0;          // relaxation time of the symmetric part (sets nu)
  double lambda = 3.0 / 16;  // TRT magic parameter
  bool incompressible = false;  // He & Luo (1997) equilibrium: rho0 = 1 in the momentum terms
};

// One face of the box: x-, x+, y-, y+, z-, z+ (index 2*axis + side).
struct Face {
  enum class Kind { periodic, wall, moving, velocity, pressure } kind = Kind::periodic;
  std::array<double, 3> u{0, 0, 0};   // moving wall velocity; inlet: vector (uniform)
  double speed = 0.0;                 // inlet: speed along the inward normal (when !u_vector)
  bool u_vector = false;
  enum class Profile { uniform, parabolic } profile = Profile::uniform;
  double rho = 1.0;                   // pressure outlet density
};

struct Shape {
  enum class Kind { box, sphere, cylinder } kind = Kind::box;
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};  // box corners (lattice coordinates)
  std::array<double, 3> center{0, 0, 0};
  double radius = 0.0;
  int axis = 2;              // cylinder axis in 3-D
  std::uint8_t flag = 1;
};

struct MeshGeometry {
  std::string file;
  bool fit_box = true;       // scale into `region` (uniform scale, centred); false: mesh coordinates are lattice coordinates
  double margin = 2.0;       // cells left free on every side of the region
  std::array<double, 6> region{0, 0, 0, 0, 0, 0};  // lo, hi; all zero: the whole lattice
  std::uint8_t flag = 1;
};

struct Units {
  bool physical = false;
  double dx = 1.0, u_phys = 1.0, u_lattice = 0.05, nu_phys = 0.0, rho_phys = 1.0;
  double dt() const noexcept { return physical ? dx * u_lattice / u_phys : 1.0; }
};

struct Output {
  long every = 0;            // 0: last step only
  std::vector<std::string> fields{"density", "velocity"};
  std::string format;        // vti, nrrd, stream ("" : from the output name)
  bool float64 = false;
  bool compress = true;
};

struct Init {
  enum class Kind { uniform, taylor_green, file } kind = Kind::uniform;
  double rho = 1.0;
  std::array<double, 3> u{0, 0, 0};
  double amplitude = 0.0;    // taylor-green U (default u_ref)
  std::string file;
};

struct Case {
  int dim = 2;
  LatticeKind lattice = LatticeKind::d2q9;
  std::array<int, 3> size{1, 1, 1};
  Collision collision;
  double re = 0.0;           // 0: not given
  double u_ref = 0.05, l_ref = 0.0;  // l_ref 0: nx
  std::array<Face, 6> faces;
  std::vector<Shape> shapes;
  std::string mask_file;     // 2-D: image whose pixel values are flags
  std::string flags_file;    // 3-D: uint8 volume of the lattice size
  std::vector<MeshGeometry> meshes;
  std::array<double, 3> force{0, 0, 0};
  Init init;
  long steps = 0;
  bool steady = false;
  double tol = 1e-6;
  long check_every = 100;
  bool bouzidi = false;       // curved_walls: interpolated bounce-back on sphere/cylinder shapes
  Output output;
  std::vector<std::array<double, 3>> probes;
  std::vector<int> forces;   // flag ids whose force is monitored
  Units units;
  std::vector<std::string> warnings;

  double nu() const noexcept { return (collision.tau - 0.5) / 3.0; }
  double lref() const noexcept { return l_ref > 0 ? l_ref : size[0]; }
  std::size_t cells() const noexcept {
    return static_cast<std::size_t>(size[0]) * size[1] * size[2];
  }
  bool periodic(int axis) const noexcept { return faces[2 * axis].kind == Face::Kind::periodic; }
};

const char* face_name(int face) noexcept;  // "x-", "x+", ...

// Checks a case for consistency and stability (tau > 1/2, paired periodic faces, inlet
// not on a periodic axis, sizes); throws Status::bad_input with the reason. Appends
// warnings (Mach number, BGK near tau = 1/2) to c.warnings.
void validate_case(Case& c, const std::string& where);

}  // namespace fest::lbm

#pragma once
// Geometry of a case on the lattice (docs/lbmsim.md "Boundary conditions", "Geometry"):
// the solid flags of the nodes (0 fluid, else the solid's flag id), built-in shapes,
// and what lies beyond each face: the class of any node, ghost nodes included.

#include <array>
#include <cstdint>
#include <vector>

#include "lbm/case.hpp"

namespace fest::lbm {

// Solid flags of the interior nodes, x fastest, then y, then z (0: fluid).
struct Flags {
  std::array<int, 3> size{1, 1, 1};
  std::vector<std::uint8_t> id;
  std::size_t index(int x, int y, int z) const noexcept {
    return static_cast<std::size_t>(x) + static_cast<std::size_t>(size[0]) * (y + static_cast<std::size_t>(size[1]) * z);
  }
};

// Marks the case's shapes: node (x, y, z) is inside when its centre (x+1/2, y+1/2, z+1/2)
// is (lattice coordinates put the halfway walls of the box at 0 and n).
Flags shape_flags(const Case& c);

// Where the surface of the case's spheres and cylinders cuts the link from node centre p
// (lattice coordinates) to p + c: the fraction q in (0, 1] of the link, or -1 when the
// far end lies in no sphere or cylinder (interpolated bounce-back, Bouzidi et al. 2001).
double link_fraction(const Case& c, const std::array<double, 3>& p, const std::array<double, 3>& dir);

// Class of a node given by global coordinates that may lie one beyond each face
// (ghost nodes). Periodic faces wrap; elsewhere the face's type decides, corners by the
// priority moving > wall > velocity > pressure (the lid rule of the cavity).
struct NodeClass {
  enum class Kind : std::uint8_t { fluid, solid, inlet, outlet } kind = Kind::fluid;
  std::uint8_t id = 0;                 // solid: flag id of an interior solid, 0 for a face wall
  int face = -1;                       // face that made a ghost node what it is
  std::array<double, 3> u{0, 0, 0};    // moving wall velocity / inlet velocity
  double rho = 1.0;                    // outlet density
};
NodeClass classify(const Case& c, const Flags& flags, int x, int y, int z);

// Velocity of a velocity face at the ghost node (x, y, z) of that face (profile applied).
std::array<double, 3> inlet_velocity(const Case& c, int face, int x, int y, int z);

}  // namespace fest::lbm

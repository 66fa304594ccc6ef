#pragma once
// The finite-element mesh of the model in material coordinates (docs/feshape.md §1.3,
// §2.3): nodes with (u, v) (latitude in [-pi/2, pi/2], longitude in [-pi, pi)), linear
// triangles, and the subdivision level of each triangle. The lat-long start mesh.

#include <array>
#include <cstdint>
#include <vector>

namespace fest::feshape {

constexpr double pi = 3.14159265358979323846;

struct Triangulation {
  std::vector<double> u, v;                 // per node
  std::vector<std::array<int, 3>> tris;     // counter-clockwise seen from outside
  std::vector<std::uint8_t> level;          // per triangle: how many bisections made it

  std::size_t nodes() const noexcept { return u.size(); }
  std::size_t elements() const noexcept { return tris.size(); }
};

// A node at a pole (u = +-pi/2): its longitude carries no information.
bool is_pole(double u) noexcept;

// The initial mesh (§2.3): `rings` rings of `meridians` nodes at u_k = -pi/2 +
// k pi/(rings+1), v_j = -pi + 2 pi j / meridians, plus two poles; quads split in two with
// the diagonal alternating per ring, fans at the poles. V = rings*meridians + 2,
// F = 2 rings meridians = 2V - 4. Needs rings >= 1, meridians >= 3.
Triangulation lat_long_mesh(int rings, int meridians);

// Longitude midpoint across the seam (+-pi): the result is in [-pi, pi).
double seam_midpoint_v(double va, double vb) noexcept;
// Material coordinates of the midpoint of edge (a, b), seam- and pole-aware (§2.2).
void edge_midpoint_uv(const Triangulation& t, int a, int b, double& u, double& v) noexcept;
// Parameter-space corners of a triangle, unwrapped across the seam; a pole corner takes
// the mean longitude of the other two (§1.3).
std::array<std::array<double, 2>, 3> unwrapped_corners(const Triangulation& t, int tri) noexcept;

}  // namespace fest::feshape

#pragma once
// The palate and the two-pass penetration avoidance of seed App. D §6 (docs/softobj.md
// §4.1): a semi-sphere (only x > centre.x constrains) and a planar strip
// p0 x + p1 y + p2 <= 0 for y in [y_a, y_b], |z| <= width/2. Pass 1 keeps the skeleton
// inside the *virtual* palate (shrunk by the offset rho) by rotating segments (lengths
// kept) on the sphere and by stepping points off the plane (lengths re-derived, coronal
// lengths of the row scaled by 1 + ratio to keep the row's area); pass 2 projects mesh
// vertices that still lie outside the true palate onto it.

#include <string_view>

#include "core/mesh.hpp"
#include "softobj/tongue.hpp"

namespace fest::softobj {

struct Palate {
  Eigen::Vector3d centre{-10, -24, 0};
  double radius = 40;
  double plane[3] = {1, 0, -14};
  double y_range[2] = {-8, 6};
  double width = 40;
  int step = 4;
};

// {"sphere": {"center": [x,y,z], "radius": R}, "strip": {"plane": [p0,p1,p2],
// "y_range": [ya,yb], "width": w}, "step": 4}. Throws fest::Error(bad_input).
Palate decode_palate(std::string_view text);

struct PalateFix {
  int sphere = 0, plane = 0;  // points moved
};

// Pass 1 on the skeleton parameters (vl0..vl3 in chain order, then the lateral points).
PalateFix palate_pass1(TongueParams& p, const Palate& palate, double rho);

// Pass 2 on a mesh: vertices outside the true palate are projected onto it (radially for
// the sphere, orthogonally for the plane); their normals are recomputed from the faces.
// Returns the number of vertices moved.
std::size_t palate_pass2(TriMesh& mesh, const Palate& palate);

}  // namespace fest::softobj

#pragma once
// Reads a case file with its geometry files (mask image, flag volume, meshes) into the
// case model and the solid flags of the lattice.

#include <string>
#include <vector>

#include "lbm/case.hpp"
#include "lbm/geometry.hpp"
#include "lbm/voxelize.hpp"

namespace fest::lbmsim {

struct LoadedCase {
  lbm::Case c;
  lbm::Flags flags;
  std::string where;  // the case's name in messages
};

// `sets`: --set overrides. Geometry file names are relative to the case file's folder.
LoadedCase load_case(const std::string& path, const std::vector<std::string>& sets);

// A mesh file as triangles (polygons split into fans); bad_input when it does not close
// ("mesh is not closed: 12 boundary edges (bunny.ply)").
lbm::TriangleSoup read_closed_mesh(const std::string& path);

}  // namespace fest::lbmsim

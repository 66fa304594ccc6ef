#pragma once
// Reads a case file with its geometry files (mask image, flag volume, meshes) into the
// case model and the solid flags of the lattice.

#include <string>
#include <vector>

#include "lbm/case.hpp"
#include "lbm/case_json.hpp"
#include "lbm/geometry.hpp"
#include "lbm/voxelize.hpp"

namespace fest::lbmsim_tool {

struct LoadedCase {
  lbm::Case c;
  lbm::Flags flags;
  std::string where;  // the case's name in messages
};

// `sets`: --set overrides (usage errors name the flag). Geometry file names are relative
// to the case file's folder.
LoadedCase load_case(const std::string& path, const std::vector<lbm::CaseOverride>& sets);

// "a.b=v" again, as --set was given.
std::string override_text(const lbm::CaseOverride& o);

// A mesh file as triangles (polygons split into fans); bad_input when it does not close
// ("mesh is not closed: 12 boundary edges (bunny.ply)").
lbm::TriangleSoup read_closed_mesh(const std::string& path);

}  // namespace fest::lbmsim_tool

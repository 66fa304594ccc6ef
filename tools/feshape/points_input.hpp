#pragma once
// Reading data points: .xyz/CSV/TSV rows "x y z [...]" (lib/feshape's codec) or the
// vertices of a mesh (PLY, OFF, OBJ, STL; faces ignored), recognised by content.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "commands.hpp"

namespace fest::feshape_tool {

// Rows, a mesh's vertices, or whichever the content is (automatic). Fails (bad_input) for fewer than 10 points.
std::vector<Eigen::Vector3d> read_points(const std::string& path, PointsFormat format);

}  // namespace fest::feshape_tool

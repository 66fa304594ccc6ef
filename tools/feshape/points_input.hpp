#pragma once
// Reading data points: .xyz/CSV/TSV rows "x y z [...]" (lib/feshape's codec) or the
// vertices of a mesh (PLY, OFF, OBJ, STL; faces ignored), recognised by content.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace fest::feshape_tool {

// format: "auto", "xyz" or "mesh". Fails (bad_input) for fewer than 10 points.
std::vector<Eigen::Vector3d> read_points(const std::string& path, const std::string& format);

}  // namespace fest::feshape_tool

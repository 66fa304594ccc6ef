#pragma once
// Reorientation to the canonical RAS+ voxel order (docs/segbrain.md): axes are permuted and
// flipped, never resampled, so the mapping back is exact.

#include <array>
#include <string>
#include <vector>

#include "core/volume.hpp"
#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct Reorientation {
  std::array<int, 3> source_axis{0, 1, 2};   // canonical axis a comes from voxel axis source_axis[a]
  std::array<bool, 3> flip{false, false, false};
  double obliquity_deg = 0;                  // largest angle between a voxel axis and its world axis
  std::string code;                          // orientation of the input voxel axes, e.g. "LSA"
};

Reorientation find_reorientation(const Volume& v);
// The canonical grid and image (float) of a volume.
Grid canonical_grid(const Volume& v, const Reorientation& r);
Image to_canonical(const Volume& v, const Reorientation& r);
// Values on the canonical grid back in the input's voxel order.
std::vector<double> from_canonical(const std::vector<double>& canon, const Volume& v, const Reorientation& r);

}  // namespace fest::segbrain

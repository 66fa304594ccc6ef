#pragma once
// Lateral extent of a structure that straddles the midsagittal plane (docs/segbrain.md §5,
// "The brainstem"): its sides taken from the CSF that bounds it where there is some, and
// bridged by straight chords where tissue runs on without a boundary (the peduncles).

#include <cstddef>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct LateralExtentStats {
  std::size_t sides = 0;       // row sides looked at (two per row of the candidate)
  std::size_t open_sides = 0;  // of those, sides that met no boundary within the limit
};

// For every row along R of `candidate` (fixed A and S) and each side of the plane
// R = plane_r_mm: from the candidate's voxel nearest the plane on that side, outward while
// the voxels lie in `within`, at most max_half_width_mm from the plane. A side that leaves
// `within` before the limit is closed there; one that reaches the limit is open, and its
// end is interpolated linearly along S between the nearest closed sides above and below
// (same A); failing that along A between the nearest closed sides of the same axial
// section; failing that it is the median of the section's closed ends (the limit when
// there is none). The ends are then smoothed by a median over the rows within 2 mm along S
// and 1 mm along A. The result holds, per row, the voxels between its two ends (not
// restricted to `within`). Positions are canonical-grid millimetres (index x spacing).
Mask lateral_extent(const Grid& g, const Mask& candidate, const Mask& within, double plane_r_mm, double max_half_width_mm,
                    LateralExtentStats* stats = nullptr);

}  // namespace fest::segbrain

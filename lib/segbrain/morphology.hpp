#pragma once
// Connected components, exact Euclidean distance transform and the morphology built on
// it, hole filling and region growing (docs/segbrain.md §3). Distances are in mm with the grid's
// anisotropic spacing. Voxels beyond the grid are "unknown", not background: the
// distance transforms see only what lies inside the field of view (edge padding).

#include <cstdint>
#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct Components {
  std::vector<std::uint32_t> label;      // 0 = not in the mask; ids 1.. in raster order
  std::vector<std::size_t> size;         // size[id], size[0] unused
};

// conn = 6, 18 or 26 (3-D); 4 or 8 label each axial slice separately.
Components connected_components(const Grid& g, const Mask& m, int conn);
Mask largest_component(const Grid& g, const Mask& m, int conn);

// Squared distance (mm²) from each voxel to the nearest voxel with target != 0
// (Felzenszwalb-Huttenlocher lower envelopes, exact); +inf when there is no target.
std::vector<double> squared_distance(const Grid& g, const Mask& target);

// Distance (mm) of each mask voxel to the nearest non-mask voxel inside the grid; 0
// outside the mask.
std::vector<double> depth(const Grid& g, const Mask& m);

// Ball of radius r mm: erode keeps voxels farther than r from the complement, dilate
// adds voxels within r of the mask; open/close compose them (exactly dual).
Mask erode(const Grid& g, const Mask& m, double r);
Mask dilate(const Grid& g, const Mask& m, double r);
Mask open(const Grid& g, const Mask& m, double r);
Mask close(const Grid& g, const Mask& m, double r);

// Background components (6-connected; 4-connected per axial slice when per_slice) that do
// not touch the grid border are added to the mask.
Mask fill_holes(const Grid& g, const Mask& m, bool per_slice);
// The same per section across `axis` (0: sagittal sections, constant R; 1: coronal,
// constant A; 2: axial, as fill_holes per slice). A brain whose CSF was stripped has the
// interhemispheric fissure open to the vertex in every coronal section but closed by the
// corpus callosum in some axial ones (docs/segbrain.md §1).
Mask fill_holes_sections(const Grid& g, const Mask& m, int axis);

// Flood fill from the seed voxels over lo <= I <= hi inside `within` (empty = all).
Mask region_grow(const Grid& g, const std::vector<float>& img, const Mask& seeds, double lo, double hi, int conn,
                 const Mask& within);

std::size_t count(const Mask& m);

}  // namespace fest::segbrain

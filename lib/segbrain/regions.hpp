#pragma once
// Region division and aggregation of the chapter's edge-based find_brain (docs/segbrain.md §3,
// helpers 2-4): the image is divided by Marr-Hildreth edges into regions, slice by
// slice; a starting region of brain is chosen in a reference slice of the upper head,
// then brain regions are aggregated over the region adjacency graph and propagated to
// the slices above and below.

#include <cstdint>
#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct Region {
  std::size_t voxels = 0;
  double mean = 0;          // mean intensity
  std::size_t slice = 0;    // axial slice (z) of a slice-wise region
  double cx = 0, cy = 0;    // centroid (voxel units, R and A)
  bool skin_contact = false;  // some voxel lies in the skin zone
};

struct Regions {
  std::vector<std::uint32_t> label;           // per voxel; 0 = edge or outside the mask
  std::vector<Region> table;                  // table[id]; table[0] unused
  std::vector<std::vector<std::uint32_t>> adjacent;  // per id, sorted, without itself
};

// Connected components of within ∧ ¬edges: 4-connected in each axial slice (per_slice)
// or 6-connected in the volume; ids in raster order. Two regions are adjacent when both
// occur in the 8-neighbourhood (in-slice; 26 in the volume) of one edge voxel.
// skin_zone marks the voxels near the head outline (skin contact).
Regions divide_into_regions(const Grid& g, const Mask& edges, const Mask& within, const Image& img, const Mask& skin_zone,
                            bool per_slice);

// The chapter's find_brain_starting_region: in the axial slice at ref_fraction of the
// head's S-extent, the largest region with mean in [lo, hi], no skin contact and
// centroid in the central half of the head's R and A extents in that slice. 0 if none.
std::uint32_t brain_starting_region(const Grid& g, const Regions& r, const Mask& head, double lo, double hi,
                                    double ref_fraction);

// The chapter's aggregate_all_brain_regions: breadth first over the adjacency graph
// from `start`, taking regions with mean in [lo, hi] and no skin contact; then slice by
// slice up and down, seeding each slice with its qualifying regions that overlap the
// accepted mask of the previous slice by >= min_overlap of their area, until the
// accepted area falls under min_area_mm2. Per-slice regions only. The mask is the
// accepted regions plus the edge voxels between them (whose in-slice 4-neighbours in
// regions are all accepted).
Mask aggregate_brain_regions(const Grid& g, const Regions& r, std::uint32_t start, double lo, double hi,
                             double min_overlap, double min_area_mm2);

}  // namespace fest::segbrain

#pragma once
// Line tracking (the chapter's "line-tracking techniques", docs/segbrain.md §3): Hessian
// tubularity as a feature and the minimum-cost path between two sets of voxels, used for
// the optic nerves. Paths are voxel index lists on the canonical grid, in order.

#include <cstddef>
#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

enum class Polarity { bright, dark, any };

// Frangi-type tubularity at scale sigma_mm (eigenvalues of the sigma²-normalised Hessian
// |l1| <= |l2| <= |l3|: a tube has l1 ~ 0 and l2 ~ l3 of the polarity's sign; alpha =
// beta = 0.5, c = half the largest Hessian norm). Computed in the bounding box of
// `within` (all when empty) grown by 3 sigma, 0 outside `within`; values in [0, 1).
Image vesselness(const Grid& g, const Image& img, double sigma_mm, Polarity polarity, const Mask& within);

// Minimum-cost 26-connected path from any voxel of `from` to any voxel of `to` (Dijkstra;
// a step costs the mean cost of its two voxels times its length in mm). The search is
// restricted to the bounding box of both sets grown by margin_mm. Returns the voxels
// from the start to the end; empty when `to` cannot be reached (or a set is empty).
// Voxels with non-finite or negative cost are impassable.
std::vector<std::size_t> line_track(const Grid& g, const Image& cost, const Mask& from, const Mask& to, double margin_mm);

// Length in mm of the polyline through every stride-th voxel centre of the path (and
// its last): stride 1 measures the 26-neighbour staircase itself, which overestimates
// an oblique line by up to 8 %; a few voxels of stride follow the line's course.
double path_length_mm(const Grid& g, const std::vector<std::size_t>& path, std::size_t stride = 1);

}  // namespace fest::segbrain

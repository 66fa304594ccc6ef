#pragma once
// Second-order edge detection (docs/segbrain.md §3, the chapter's Marr-Hildreth operator): the
// Laplacian of the Gaussian-smoothed image and its zero crossings.

#include "segbrain/grid.hpp"

namespace fest::segbrain {

// LoG = sum over the axes of d²(G_sigma * I)/dx² (per mm²). in_plane: the Gaussian and
// the Laplacian act within each axial slice only (R and A axes), the scope slice(axial).
Image laplacian_of_gaussian(const Grid& g, const Image& img, double sigma_mm, bool in_plane);

// Marr-Hildreth edges of a LoG image: voxel p is an edge where LoG(p) LoG(q) < 0 for a
// 4-neighbour q in the axial slice (in_plane) or a 6-neighbour (volume) and
// |LoG(p) - LoG(q)| >= slope * max |LoG| (|LoG| under 1e-6 max |LoG| counts as zero,
// no sign); of p and q the one with the smaller |LoG| (the
// one nearer the crossing; p on a tie) is marked, so edges are one voxel wide.
Mask zero_crossings(const Grid& g, const Image& log, double slope, bool in_plane);

// laplacian_of_gaussian followed by zero_crossings.
Mask marr_hildreth(const Grid& g, const Image& img, double sigma_mm, double slope, bool in_plane);

}  // namespace fest::segbrain

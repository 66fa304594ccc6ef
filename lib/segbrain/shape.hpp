#pragma once
// Location and shape operators for the objects inside the brain (docs/segbrain.md §3): where a
// mask lies, how it mirrors about a sagittal plane, which of its parts lie near a point,
// and growth that stays inside another object. Positions are canonical-grid millimetres
// (index × spacing along R, A, S), so rules compare them with each other, never with
// scanner coordinates.

#include <array>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

using Point = std::array<double, 3>;

// Mean position of the mask's voxels (NaN when empty).
Point centroid_mm(const Grid& g, const Mask& m);

// Smallest and largest voxel position of the mask per axis: {R0, R1, A0, A1, S0, S1}
// (NaN when empty).
std::array<double, 6> bbox_mm(const Grid& g, const Mask& m);

// Voxels whose position along `axis` (0 R, 1 A, 2 S) is below (or above) value_mm.
Mask halfspace(const Grid& g, int axis, bool below, double value_mm);

// The components (conn 6/18/26) of at least min_ml whose centroid lies within max_dist_mm
// of `near`.
Mask components_near(const Grid& g, const Mask& m, int conn, double min_ml, const Point& near, double max_dist_mm);

// The components (conn 6/18/26) whose volume lies in [min_ml, max_ml].
Mask components_sized(const Grid& g, const Mask& m, int conn, double min_ml, double max_ml);

// The two components (conn 6/18/26) that mirror each other best about the sagittal
// plane R = plane_r_mm: left-right distance of their centroids within [min_dist_mm,
// max_dist_mm], smallest |midpoint R - plane| + |dA| + |dS|. Empty when no pair fits;
// `score_mm` receives that sum (infinity when empty).
Mask symmetric_pair(const Grid& g, const Mask& m, int conn, double plane_r_mm, double min_dist_mm, double max_dist_mm,
                    double& score_mm);

// Voxels of `within` reachable from `m` by a path inside `within` no longer than r_mm
// (26-neighbour steps of their Euclidean length; m itself is kept).
Mask geodesic_dilate(const Grid& g, const Mask& m, const Mask& within, double r_mm);

// Dice of the mask and its mirror image about the sagittal plane R = plane_r_mm.
double mirror_dice(const Grid& g, const Mask& m, double plane_r_mm);

}  // namespace fest::segbrain

namespace fest::segbrain {

// Sagittal plane R = c (mm) about which the image inside the mask is most symmetric:
// c within ±search_mm of the mask's centroid, in half-voxel steps, maximising the
// correlation of the intensities with their mirror images (no tilt: the axes of the
// canonical grid are taken as the head's).
double midsagittal_r_mm(const Grid& g, const Image& img, const Mask& m, double search_mm);

}  // namespace fest::segbrain

#pragma once
// Measurements behind the verification predicates (docs/segbrain.md §3); each is a reconstruction
// of a check the chapter names ("no connection to skin contour", "reasonable contour
// length", "comparable to adjacent slices").

#include <utility>
#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

// Median of the upper half (the 75th percentile) of intensities among mask voxels whose
// depth lies in the top `frac` of depths: the deep head centre, white matter on T1.
double deep_intensity(const Grid& g, const Image& img, const Mask& mask, double frac);
// The same with the mask's depth map already computed.
double deep_intensity(const Image& img, const Mask& mask, const std::vector<double>& depth, double frac);

// Fraction of `m` voxels within dist_mm of the outline of `head` (depth <= dist_mm).
double skin_contact_fraction(const Grid& g, const Mask& m, const Mask& head, double dist_mm);
// The same with the head's depth map already computed.
double skin_contact_fraction(const Mask& m, const std::vector<double>& head_depth, double dist_mm);

// Over axial slices where m covers at least 10 cm², the median ratio of m's
// compactness perimeter/sqrt(area) to head's: ragged, leaking masks make it large.
double contour_length_ratio(const Grid& g, const Mask& m, const Mask& head);

// Over adjacent axial slice pairs both >= 10 cm²: the largest relative area change and
// the smallest Dice. (0, 1) when there is no such pair.
std::pair<double, double> slice_consistency(const Grid& g, const Mask& m);

// Dice coefficient of two masks (1 when both are empty).
double dice(const Mask& a, const Mask& b);

}  // namespace fest::segbrain

#pragma once
// Intensity operators: Gaussian smoothing and histogram analysis (docs/segbrain.md §3).

#include "segbrain/grid.hpp"

namespace fest::segbrain {

// Separable Gaussian of standard deviation sigma_mm, kernel radius ceil(3 sigma / spacing)
// per axis, borders replicated.
Image gaussian_smooth(const Grid& g, const Image& img, double sigma_mm);

// The p-th percentile (0..100, nearest rank) of the image inside mask (all when mask is
// empty). Returns NaN when no voxel is selected.
double percentile(const Image& img, const Mask& mask, double p);

// Otsu's threshold on a 256-bin histogram of the voxels inside mask (all when empty):
// the bin edge maximising the between-class variance.
double otsu_threshold(const Image& img, const Mask& mask);

// lo <= I <= hi.
Mask threshold(const Image& img, double lo, double hi);

// Voxel-wise logic of two masks of one grid: a and b, a or b, a and not b.
enum class MaskLogic { both, either, first_only };
Mask combine(const Mask& a, const Mask& b, MaskLogic op);

// Fraction of mask voxels with lo <= I <= hi.
double fraction_within(const Image& img, const Mask& mask, double lo, double hi);

}  // namespace fest::segbrain

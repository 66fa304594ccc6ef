#pragma once
// Tissue classes by intensity (docs/segbrain.md §3 tissue_classes / classify): 1-D k-means inside
// a mask and nearest-mean labelling, for the grey/white matter split of --tissue.

#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

// K class means (K >= 2) of the intensities inside mask: k-means started at the
// percentiles 10..90 spread evenly, `iterations` Lloyd steps, returned in increasing
// order. Empty when the mask is empty.
std::vector<double> kmeans_1d(const Image& img, const Mask& mask, int k, int iterations = 30);

// Mask voxels whose nearest class mean is means[index].
Mask nearest_class(const Image& img, const Mask& mask, const std::vector<double>& means, std::size_t index);

}  // namespace fest::segbrain

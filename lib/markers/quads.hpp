#pragma once
// Candidate quadrilaterals in a grey image (docs/markerpose.md §2, after Kato &
// Billinghurst's "thick black border" search): local-mean (adaptive) thresholding at a
// few window sizes, the outer contours of the dark components, a polygon fit, and the
// convex four-vertex polygons of sufficient size.

#include <vector>

#include <opencv2/core.hpp>

#include "markers/pose.hpp"

namespace fest::markers {

struct QuadOptions {
  double min_side_px = 6;                  // shortest side of a candidate
  double max_side_fraction = 0.95;         // longest side, as a fraction of the image's larger side
  std::vector<int> windows{7, 41};         // adaptive-threshold windows (full-resolution pixels)
  int half_resolution_window = 41;         // windows from this size threshold the half-size image
  double threshold_offset = 7;             // a pixel is dark when below the local mean minus this
  double polygon_epsilon = 0.04;           // polygon fit tolerance, fraction of the perimeter
};

// Corners come clockwise in the image (y down), starting anywhere; duplicates found at
// several windows are merged (the first found is kept).
std::vector<Corners> find_quads(const cv::Mat& grey8, const QuadOptions& options);

}  // namespace fest::markers

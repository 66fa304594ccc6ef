#pragma once
// Sub-pixel corners by fitting a blurred-step model to the pixels along each side
// (docs/markerpose.md §2.4). The edge-point line fit (corner_refine.hpp) gives the
// start; here every pixel within half a cell of a side is explained by
//   I(p) = A(t) + (B(t) - A(t)) Phi(d(p) / s)
// with d the signed distance of p from the side's line (outward: from the dark border
// to the light surround), Phi the normal CDF (a straight edge seen through a Gaussian
// blur of s px), A and B the dark and light grey levels (constant along the side, or
// linear in the position t along it when the band is wide enough to tell a level change
// from a turn of the line: the illumination gradient of a large marker). The line, the
// levels and s are fitted by Gauss-Newton on the squared grey-level residuals -- the
// maximum-likelihood estimate under independent Gaussian noise -- and neighbouring lines
// are intersected. The levels are local to each side, so an illumination gradient moves
// no edge (a fixed threshold would).

#include <opencv2/core.hpp>

#include "markers/camera_model.hpp"
#include "markers/pose.hpp"

namespace fest::markers {

struct EdgeModelOptions {
  double band_cells = 0.5;      // half-width of the band fitted, in cells: the next edges
                                // (data cells inside, the quiet zone's end outside) stay
                                // at least half a cell away
  double band_min_px = 1.5, band_max_px = 5;
  double end_margin = 0.08;     // fraction of the side left out at each end (the corners)
  int iterations = 10;
  double linear_levels_ratio = 2.5;  // levels vary along the side when band >= ratio * s
};

// Refines `corners` (clockwise on screen, as from refine_corners) of a marker with
// `cells` cells across. `noise_sigma` (grey levels, image_noise()) bounds the residual:
// a side whose fit leaves an RMS residual above 3 sigma + 3 grey levels (an occluder, a
// foreign edge) rejects the refinement. With a distorting `camera` the model is fitted in
// ideal (undistorted) pixel coordinates and the corners distorted back. Returns false and
// leaves the corners as given when any side fails.
bool fit_edge_model(const cv::Mat& grey8, Corners& corners, int cells, const CameraModel* camera, double noise_sigma,
                    const EdgeModelOptions& options = EdgeModelOptions());

}  // namespace fest::markers

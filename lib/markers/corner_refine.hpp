#pragma once
// Sub-pixel corners from the marker's four edges (docs/markerpose.md §2.3): along each
// side, the position of the steepest dark-to-light step is found on short profiles
// across the edge (bilinear samples, parabolic peak of the derivative); a straight line
// is fitted to these points (total least squares, weighted by edge strength, outliers
// from occlusion dropped) and neighbouring lines are intersected. This is ARToolKit's
// line-fit corner with a sub-pixel edge locator, and it is unbiased under symmetric blur.

#include <opencv2/core.hpp>

#include "markers/camera_model.hpp"
#include "markers/pose.hpp"

namespace fest::markers {

// `cells` is the number of cells across the marker (border included): profiles stay
// within 0.4 cell of the edge so that the data cells next to the border do not disturb
// them. With a distorting `camera`, the edge points are undistorted before the lines are
// fitted (a straight edge is straight only in the ideal image) and the intersections are
// distorted back. Returns false when a side has too few edge points (the corners are left
// as given).
bool refine_corners(const cv::Mat& grey8, Corners& corners, int cells, const CameraModel* camera = nullptr,
                    int passes = 2);

}  // namespace fest::markers

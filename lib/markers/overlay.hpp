#pragma once
// The AR view (the MagicBook's fig. 3.6b; docs/markerpose.md §5.2): a mesh given in the
// marker frame drawn over the camera image at the marker's pose, through
// lib/reflectance's rasteriser (ideal pinhole) and, for a distorting lens, resampled into
// the distorted image so that it lands where the real lens images the model.

#include <vector>

#include <opencv2/core.hpp>

#include "markers/camera_model.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::markers {

struct OverlayStyle {
  cv::Vec3b colour{240, 170, 40};  // R, G, B
  double opacity = 0.85;
  int threads = 1;
};

// Coverage of the mesh at `pose` in the distorted camera image: 1 byte per pixel,
// row-major, 1 where a triangle covers the pixel centre.
std::vector<std::uint8_t> overlay_mask(const reflectance::TriangleMesh& mesh, const CameraModel& camera,
                                       const Pose& pose, int threads = 1);

// Draws the mesh (Lambert-shaded with a headlight) into `rgb8` (CV_8UC3, R,G,B, the
// camera's size) at every pose in `poses`.
void draw_overlay(cv::Mat& rgb8, const reflectance::TriangleMesh& mesh, const CameraModel& camera,
                  const std::vector<Pose>& poses, const OverlayStyle& style = {});

// A closed cube of side `side` standing on the marker: x, y in [-side/2, side/2], z in
// [0, side] (z out of the marker, towards the viewer).
reflectance::TriangleMesh marker_cube(double side);

}  // namespace fest::markers

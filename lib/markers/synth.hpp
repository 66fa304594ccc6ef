#pragma once
// The synthetic marker generator (docs/markerpose.md §5): markers drawn at known poses
// through the camera model (perspective and lens distortion, 4 x 4 supersampling), over a
// cluttered background, with the degradations of the benchmark: low contrast, an
// illumination gradient, partial occlusion of the interior, Gaussian blur and noise.
// Deterministic for a given seed. The ground truth is the pose and the projected corners.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "markers/camera_model.hpp"
#include "markers/dictionary.hpp"
#include "markers/pose.hpp"

namespace fest::markers {

// What is printed: a binary marker (n x n code in a one-cell black border) or an
// ARToolKit pattern marker (picture in the middle half, black border around it), with a
// white quiet zone of `quiet_zone` cells (binary) or side/8 (pattern) around it.
struct MarkerArt {
  int bits = 0;              // binary: n (0 for a pattern marker)
  std::uint64_t code = 0;    // binary: dictionary code
  cv::Mat picture;           // pattern: 8-bit grey picture inside the border
  double quiet_zone = 1.0;   // binary: white cells around the border
};

MarkerArt binary_art(const Dictionary& dict, int id);

struct PlacedMarker {
  MarkerArt art;
  double side = 1;  // outer side of the black border, in the pose's length unit
  Pose pose;        // marker -> camera
};

struct Degradation {
  double black = 20, white = 235;  // grey levels of the printed black and white
  double gradient = 0;             // illumination gain varies by +-gradient/2 across the image
  double occlusion = 0;            // fraction of the interior (data area) covered by a grey patch
  double blur_sigma = 0;           // Gaussian blur, pixels
  double noise_sigma = 0;          // Gaussian noise, grey levels
  bool clutter = true;             // textured background with dark rectangles (distractors)
};

// 8-bit grey image of camera.width x camera.height. A `photo` (8-bit grey, the camera's
// size) replaces the synthetic background: a marker "printed" into a real scene.
cv::Mat render_scene(const CameraModel& camera, const std::vector<PlacedMarker>& markers, const Degradation& d,
                     std::uint64_t seed, const cv::Mat& photo = cv::Mat());

// The marker's four outer corners projected through the camera (with distortion), in
// detection order (top-left, top-right, bottom-right, bottom-left).
Corners project_corners(const CameraModel& camera, const Pose& pose, double side);

// A printable marker image: `pixels_per_cell` pixels per cell, quiet zone included.
cv::Mat draw_marker(const Dictionary& dict, int id, int pixels_per_cell, int quiet_cells = 1);

// Pose with the marker centre at `distance` along a ray through the image point (u, v)
// (ideal pixels), turned by `tilt_deg` about an in-plane axis at angle `axis_deg`, and by
// `roll_deg` about its normal. At tilt 0 the marker faces the centre of projection, so
// the tilt is the viewing angle (between the marker's normal and the line of sight).
Pose pose_facing(const CameraModel& camera, double u, double v, double distance, double tilt_deg, double axis_deg,
                 double roll_deg);

}  // namespace fest::markers

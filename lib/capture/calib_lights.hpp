#pragma once
// Light position calibration with chrome spheres (docs/capture.md §5): each sphere
// of known radius seen in an image gives its centre (from its outline) and, through the
// mirror reflection at its highlight, a ray toward the light; the light is the
// least-squares intersection of the rays of all spheres and views.

#include <vector>

#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"

namespace fest::capture {

// One sphere found in an image, in pixels.
struct SphereImage {
  cv::Point2d centre;                // of the outline (image of the sphere, not of its centre)
  double radius = 0;                 // mean outline radius
  std::vector<cv::Point2d> outline;  // sub-pixel edge points
  cv::Point2d highlight;             // peak of the brightest blob (its centroid when saturated)
  double highlight_peak = 0;         // its brightest value, 0..1
};

struct SphereDetectOptions {
  double min_radius_px = 8;          // smaller blobs are not spheres
  double min_circularity = 0.8;      // 4 pi area / perimeter^2 of the outline
};

// Spheres standing out brighter than the background (a dark enclosure, as the chapter's
// studio), each with a highlight brighter than its surroundings. `grey` is float 0..1.
// Spheres touching the image border are left out. Ordered left to right.
std::vector<SphereImage> detect_spheres(const cv::Mat& grey, const SphereDetectOptions& options = {});

// What one sphere says about the light, in the camera frame C (mm).
struct SphereRay {
  cv::Vec3d centre;     // sphere centre from the outline's cone of tangent rays and the radius
  cv::Vec3d origin;     // highlight point on the sphere
  cv::Vec3d direction;  // unit, toward the light: the viewing ray mirrored about the normal
};

SphereRay sphere_ray(const SphereImage& sphere, const Intrinsics& camera, double radius_mm);

struct LightFit {
  cv::Vec3d position;
  double residual_rms_mm = 0;            // RMS distance from the position to the rays
  std::vector<double> ray_distance_mm;   // per ray
};

// Least-squares intersection: minimises sum_i |(I - d_i d_i^T)(q - o_i)|^2. Needs >= 2
// rays that are not nearly parallel; throws fest::Error (bad_input) otherwise.
LightFit triangulate_light(const std::vector<SphereRay>& rays);

}  // namespace fest::capture

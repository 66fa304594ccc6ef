#pragma once
// Lumitexel generation (docs/brdffit.md §4; chapter 8 §8.4.3, §8.6.3): resampling
// registered HDR images onto the surface.
//
//  1. Home image: every triangle goes to the image in which it covers the most pixels,
//     among the images where it faces the camera and at least half of its rasterized
//     pixels pass the depth test.
//  2. One lumitexel per pixel centre covered by the triangle in its home image (the point
//     where the pixel's ray meets the triangle; normal interpolated from the vertices).
//  3. One sample per image where the point is visible (depth test), lit (shadow map of the
//     image's light), both cosines above min_cos, inside the mask and valid; the radiance is
//     bilinearly resampled and normalised, r = L d^2 / I.
//  4. Lumitexels with fewer than min_samples samples are dropped.
//
// Images are requested one at a time through a callback, so only one HDR image is in
// memory at once (the depth buffers of the distinct cameras are kept).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "brdffit/lumitexel.hpp"
#include "reflectance/camera.hpp"
#include "reflectance/render.hpp"
#include "reflectance/triangle_mesh.hpp"
#include "core/progress_callback.hpp"

namespace fest::brdffit {

// One HDR photograph's geometry: the camera that took it and the light that lit it.
struct ImageView {
  reflectance::PinholeCamera camera;
  reflectance::PointLight light;
};

// One HDR photograph's pixels, as the loader hands them over.
struct ImagePixels {
  cv::Mat radiance;  // CV_32FC3, linear RGB, camera.width x camera.height
  cv::Mat mask;      // CV_8U, nonzero = object; empty = everything
  cv::Mat valid;     // CV_32F or CV_8U, 0 = invalid (saturated); empty = all valid
};

struct LumitexelOptions {
  double min_cos = 0.05;
  double depth_eps = 0;      // world units; 0: 0.2 % of the bounding-box diagonal
  int min_samples = 2;
  int shadow_resolution = 0;  // 0: the largest image side, within 512..8192
  int threads = 1;
  ProgressFn progress;  // steps: the home images, then every image twice (points, samples)
};

struct LumitexelReport {
  std::size_t triangles_with_home = 0;
  std::size_t candidates = 0;         // lumitexels before the min_samples cut
  std::size_t dropped = 0;            // with fewer than min_samples samples
  std::size_t samples = 0;
  std::size_t rejected_occluded = 0;  // per (point, image) pair
  std::size_t rejected_shadowed = 0;
  std::size_t rejected_grazing = 0;   // u_z or v_z <= min_cos
  std::size_t rejected_mask = 0;      // outside the image, the mask or the valid pixels
  std::size_t nonfinite_pixels = 0;   // NaN/Inf radiance met (the sample is dropped)
  std::vector<double> seconds;        // per stage: home images, points, samples
};

using ImageLoader = std::function<ImagePixels(std::size_t image)>;

// Builds the set; `set.images` and `set.mesh_sha256` are left for the caller. Throws
// fest::Error (bad_input) when an image's size differs from its camera's, and
// (bad_input) when no lumitexel has min_samples samples.
LumitexelSet build_lumitexels(const reflectance::TriangleMesh& mesh, const std::vector<ImageView>& views,
                              const ImageLoader& load, const LumitexelOptions& options, LumitexelReport* report);

// Step 1 alone: the home image of every triangle (-1 when it has none) and the number of
// pixels it covers there. A rasterized pixel of a triangle "passes the depth test" when
// the triangle is the visible surface at that pixel centre.
struct HomeAssignment {
  std::vector<std::int32_t> image;
  std::vector<std::uint32_t> pixels;
};
HomeAssignment assign_home_images(const reflectance::TriangleMesh& mesh, const std::vector<ImageView>& views,
                                  int threads);

}  // namespace fest::brdffit

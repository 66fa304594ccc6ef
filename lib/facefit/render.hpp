#pragma once
// A small z-buffered rasteriser for looking at results: frontal orthographic view
// (u = s x + c_u, v = −s y + c_v), per-pixel depth test, barycentric interpolation of a
// per-vertex value and Lambert shading from a light at the viewer.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace fest::facefit {

struct Raster {
  int width = 0, height = 0;
  std::vector<float> value;    // interpolated per-vertex value; NaN where no surface
  std::vector<float> shading;  // |n·view| in [0, 1]; 0 where no surface
};

// shape: interleaved xyz; values: one per vertex (may be empty: value stays NaN).
Raster rasterise(const Eigen::VectorXd& shape, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                 const std::vector<double>& values, int width, int height, double scale, const Eigen::Vector2d& center);

// Which vertices of a shape given in image space (u, v, depth towards the viewer, as
// to_image_space makes it) are seen by the camera: a depth buffer at image resolution,
// a vertex is visible when nothing lies in front of it by more than `tolerance` (px).
// Vertices outside the image are not visible.
std::vector<std::uint8_t> vertex_visibility(const Eigen::VectorXd& image_shape,
                                            const std::vector<std::array<std::uint32_t, 3>>& triangles, int width,
                                            int height, double tolerance);

}  // namespace fest::facefit

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

}  // namespace fest::facefit

#pragma once
// A picture of the lit scene for looking at results: lib/reflectance's rasteriser gives
// the visible triangle and barycentrics per pixel, and the per-vertex values are
// interpolated across it (Gouraud shading, as radiosity viewers draw baked lighting).

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "commands.hpp"
#include "core/image.hpp"

namespace fest::radiosity_tool {

struct ViewMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector3d> values;  // per vertex, interpolated
};

// RGB float image (CV_32FC3), background 0. The camera comes from `camera`, or looks
// along +z at the box of the positions from in front of it.
cv::Mat render_values(const ViewMesh& mesh, const CameraArgs& camera, int threads);

// 8-bit RGB image from the float one: `scale` times the value, then `gamma` (1/2.2 for
// linear radiance, 1 for display colours already encoded).
Image to_display(const cv::Mat& values, double scale, double gamma);

}  // namespace fest::radiosity_tool

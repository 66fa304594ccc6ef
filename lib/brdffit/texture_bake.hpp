#pragma once
// Baking surface functions into a texture atlas (texture_atlas.hpp): every texel whose
// centre lies within the atlas' gutter of a triangle of its chart shows the closest point
// of the nearest such triangle, so the gutter repeats the chart's border values and
// bilinear filtering never mixes a chart with its neighbour or the empty background.
//
// The maps are the glTF 2.0 metallic-roughness set (docs/brdffit.md §6, `export`):
// base colour (linear; the writer encodes sRGB), metallic-roughness (glTF's channels: G =
// roughness, B = metallic; R is unused and set to 1), and a tangent-space normal map
// against the tangent frames of corner_tangents().

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "brdffit/texture_atlas.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit {

// Which surface point every texel shows (row-major, width x height).
struct TexelSurface {
  int width = 0, height = 0;
  std::vector<std::int32_t> triangle;  // -1: no triangle of the texel's chart within the gutter
  std::vector<Eigen::Vector3d> bary;   // barycentric coordinates of the point shown
  std::vector<float> distance;         // texels from the centre to that point (0 inside)
};
TexelSurface texel_surface(const TextureAtlas& atlas);

// glTF TANGENT per triangle corner (xyz unit, w = handedness +-1): the direction of
// increasing u of the triangle's atlas map, made orthogonal to the corner's normal; the
// bitangent is cross(normal, tangent) * w, as glTF 2.0 defines it. A triangle whose UVs
// are degenerate gets any tangent orthogonal to the normal.
std::vector<std::array<Eigen::Vector4d, 3>> corner_tangents(const reflectance::TriangleMesh& mesh,
                                                          const TextureAtlas& atlas);

// What a surface point looks like to a metallic-roughness viewer.
struct PbrPoint {
  Eigen::Vector3d base_color = Eigen::Vector3d::Zero();  // linear, [0, 1]
  double roughness = 1, metallic = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // world; zero: the interpolated mesh normal
};
using PbrSurface = std::function<PbrPoint(std::uint32_t triangle, const Eigen::Vector3d& bary)>;

struct PbrMaps {
  cv::Mat base_color;          // CV_32FC3, linear RGB
  cv::Mat metallic_roughness;  // CV_32FC3: (1, roughness, metallic)
  cv::Mat normal;              // CV_32FC3: tangent-space unit normal, components in [-1, 1]
  cv::Mat coverage;            // CV_8UC1: 255 where a triangle is within the gutter
};

// Evaluates `surface` at every covered texel (empty texels: black, roughness 1, normal
// (0, 0, 1)). The tangent-space normal n_t = (n.T, n.B, n.N) uses the frame a glTF viewer
// interpolates: T and N barycentric blends of the corner tangents and mesh normals,
// normalised, B = cross(N, T) w. `threads` workers split the rows (0: all cores).
PbrMaps bake_pbr(const reflectance::TriangleMesh& mesh, const TextureAtlas& atlas, const TexelSurface& texels,
                 const PbrSurface& surface, int threads = 0);

}  // namespace fest::brdffit

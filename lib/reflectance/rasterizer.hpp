#pragma once
// A CPU rasterizer for triangle meshes seen by a pinhole camera (the ideal projection of
// camera.hpp). One sample per pixel, at the pixel centre; coverage is inclusive on edges
// (a centre exactly on a shared edge belongs to both triangles, so closed meshes have no
// cracks), the nearest fragment wins, equal depths go to the lower triangle index: the
// result is the same for every thread count. Triangles with a vertex at or behind the
// near plane (z_cam <= 1e-9) are not drawn (the objects of brdffit lie in front of the
// camera). Triangles are scanned as one span per row (triangle_scan.hpp), the span's ends
// settled by the per-pixel test itself.
//
// The product is a visibility buffer: per pixel the triangle, its camera depth and the
// perspective-correct barycentric coordinates of the surface point under the pixel
// centre. Shading, masks, silhouettes, depth tests and shadow maps are all read from it.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "reflectance/camera.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::reflectance {

struct Fragments {
  int width = 0, height = 0;
  std::vector<std::int32_t> triangle;  // -1 where no triangle covers the pixel centre
  std::vector<float> depth;            // z_cam of the visible point; +inf on background
  std::vector<float> b1, b2;           // barycentrics of vertices 1 and 2 (b0 = 1 - b1 - b2)

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  bool covered(int x, int y) const { return triangle[index(x, y)] >= 0; }
};

struct RasterOptions {
  int threads = 1;
  bool barycentrics = true;  // false: triangle ids and depth only
};

Fragments rasterize(const TriangleMesh& mesh, const PinholeCamera& camera, const RasterOptions& options = {});

// Coverage only, as 0/1 bytes in row-major order (silhouette registration, docs/brdffit.md §6):
// the same inclusive pixel-centre rule, no depth.
std::vector<std::uint8_t> rasterize_silhouette(const TriangleMesh& mesh, const PinholeCamera& camera, int threads = 1);

// Pixel centres inside each triangle's projection, whatever lies in front of it (the
// "rasterized pixels" of a triangle when its visibility is judged).
std::vector<std::uint32_t> projected_pixel_counts(const TriangleMesh& mesh, const PinholeCamera& camera);

// The world point and interpolated unit shading normal under pixel `i` of `f`.
Eigen::Vector3d fragment_point(const TriangleMesh& mesh, const Fragments& f, std::size_t i);
Eigen::Vector3d fragment_normal(const TriangleMesh& mesh, const Fragments& f, std::size_t i);

// Depth map rendered from a point light, looking at the mesh's bounding sphere (which
// must not contain the light): a point is lit when no surface lies nearer to the light
// along its direction, within `eps` (world units). The test takes the farthest of the
// 2 x 2 texels around the point's projection, which keeps lit surfaces free of
// self-shadowing "acne" at the price of a one-texel softer shadow edge.
struct ShadowMap {
  PinholeCamera view;
  Fragments fragments;
  double eps = 0;
  bool lit(const Eigen::Vector3d& world_point) const;
};

// Throws fest::Error (bad_input) when the light lies inside the bounding sphere.
ShadowMap make_shadow_map(const TriangleMesh& mesh, const Eigen::Vector3d& light_position, int resolution, double eps,
                          int threads = 1);

}  // namespace fest::reflectance

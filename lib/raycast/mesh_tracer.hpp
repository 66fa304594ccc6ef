#pragma once
// Opaque triangle meshes in the ray caster (volrender --mesh; docs/volrender.md "Modes"):
// a bounding-volume hierarchy over the triangles and exact ray-triangle intersection
// (Moller-Trumbore), so every camera -- off-axis and mirror included -- sees the mesh with
// the same rays as the volume. Each ray stops at the first hit and the shaded mesh colour
// is composited behind the volume colour accumulated in front of it.

#include <array>
#include <cstdint>
#include <vector>

#include "raycast/camera.hpp"
#include "raycast/render.hpp"

namespace fest::raycast {

class MeshTracer {
 public:
  // xyz: 3 per vertex (world units); colour: diffuse RGB (linear) lit by a head light with
  // ambient 0.25, two-sided.
  MeshTracer(std::vector<float> xyz, std::vector<std::array<std::uint32_t, 3>> triangles, std::array<double, 3> colour);
  SurfaceHit trace(const Ray& ray) const;
  // The callback form render() takes.
  static SurfaceHit callback(const void* self, const Ray& ray) { return static_cast<const MeshTracer*>(self)->trace(ray); }

 private:
  struct Node {
    float lo[3], hi[3];
    std::uint32_t first, count;  // leaf: triangles [first, first + count); inner: count = 0, children first, first + 1
  };
  std::uint32_t build(std::uint32_t begin, std::uint32_t end);
  std::vector<float> xyz_;
  std::vector<std::array<std::uint32_t, 3>> tri_;
  std::vector<Node> nodes_;
  std::array<double, 3> colour_;
};

}  // namespace fest::raycast

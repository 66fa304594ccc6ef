#pragma once
// A scene read through assimp, flattened: what the assimp plugin hands to formats/mesh
// (assimp_plugin_api.h). Standard containers only, so that neither side needs the other's
// headers: assimp's stay inside the plugin, OpenMesh's outside it.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fest::formats {

struct AssimpScene {
  // Every mesh of every node, its node's transform (and its parents') applied, one after
  // another: 3 doubles per vertex.
  std::vector<double> positions;
  // Per vertex, present only when every mesh of the scene has them (else counted below):
  std::vector<double> normals;           // 3 per vertex, transformed by the inverse transpose
  std::vector<float> colors;             // RGBA in [0, 1], 4 per vertex (colour set 0)
  std::vector<float> texcoords;          // u v per vertex (channel 0)
  std::vector<std::uint32_t> triangles;  // 3 vertex indices per triangle (polygons triangulated)
  // What the scene holds that a fest mesh cannot: ("bones", 12), ("animations", 1) ...
  // Geometry parts (points, lines, extra channels, per-mesh attributes only some meshes
  // have, skinning, morph targets) go to `lost`; appearance and scene parts (materials,
  // textures, cameras, lights) to `not_geometry`.
  std::vector<std::pair<std::string, std::size_t>> lost;
  std::vector<std::pair<std::string, std::size_t>> not_geometry;
  std::string format;  // the extension hint it was read with ("gltf", "3ds", ...)
};

}  // namespace fest::formats

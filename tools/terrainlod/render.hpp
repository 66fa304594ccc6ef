#pragma once
// A small z-buffered software rasterizer for previews of extracted views: faces in their
// colours (the tile level), Lambert-shaded from a fixed sun, seen through the camera.

#include <string>

#include "core/mesh.hpp"
#include "terrainlod/extract.hpp"

namespace fest::terrainlod_tool {

// PNG bytes of the mesh seen by `camera` (camera.width x camera.height pixels).
std::string render_png(const Mesh& mesh, const terrainlod::Camera& camera);

}  // namespace fest::terrainlod_tool

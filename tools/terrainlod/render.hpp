#pragma once
// A small z-buffered software rasterizer for previews of extracted views: faces in their
// colours (the tile level), Lambert-shaded from a fixed sun, seen through the camera; or,
// for a textured pyramid, each face sampling its tile's texture (bilinear, perspective-
// correct texture coordinates).

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/mesh.hpp"
#include "terrainlod/extract.hpp"

namespace fest::terrainlod_tool {

// Textures for the renderer: face f samples images[face_image[f]] at its vertices'
// texture coordinates (mesh texcoords, v up). Images are 8-bit grey or RGB.
struct RenderTextures {
  std::vector<cv::Mat> images;
  std::vector<int> face_image;
};

// PNG bytes of the mesh seen by `camera` (camera.width x camera.height pixels).
std::string render_png(const Mesh& mesh, const terrainlod::Camera& camera, const RenderTextures* textures = nullptr);

}  // namespace fest::terrainlod_tool

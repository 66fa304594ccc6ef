#pragma once
// glTF 2.0 export (docs/brdffit.md §6, `export`): a metallic-roughness approximation of
// the Lafortune materials (lib/brdffit/pbr_appearance.hpp says what is approximated) for
// viewers that know only PBR materials.
//
// - encode_gltf: untextured (`export --flat`): one primitive and one constant material per
//   BRDF, triangles by their (majority) material; one .gltf with the buffer as a data URI.
// - encode_textured_gltf: the spatially varying result as textures in a texture atlas:
//   one primitive, three vertices per triangle (atlas charts cut the mesh), POSITION,
//   NORMAL, TEXCOORD_0 and, with a normal map, TANGENT (the frames the normal map was
//   baked against); one material with baseColorTexture (sRGB PNG), metallicRoughnessTexture
//   (G roughness, B metallic) and normalTexture. Samplers: linear, no mipmaps (a chart's
//   gutter protects bilinear lookups, not the coarse levels of a mip chain), clamp to edge.

#include <string>
#include <vector>

#include "brdffit/texture_atlas.hpp"
#include "reflectance/render.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit_tool {

// Materials per triangle (vertex weights: the largest weight of the triangle's first vertex).
std::string encode_gltf(const reflectance::TriangleMesh& mesh, const reflectance::SurfaceMaterials& materials);

// Encoded PNG files of the baked maps; normal is empty when there is no normal map.
struct PngTextures {
  std::string base_color, metallic_roughness, normal;
};

enum class ImageStorage {
  files,     // PNG files beside the .gltf, named by image_names
  data_uri,  // PNGs inside the .gltf as base64 data URIs (for standard output)
  glb,       // one binary .glb holding the JSON, the geometry and the PNGs
};

struct GltfFile {
  std::string bytes;  // the .gltf text or the .glb
  // With ImageStorage::files: (file name, PNG bytes) to write beside the .gltf.
  std::vector<std::pair<std::string, std::string>> images;
};

// image_stem: the file names' prefix with ImageStorage::files (STEM_basecolor.png,
// STEM_metalrough.png, STEM_normal.png), relative to the .gltf's folder.
GltfFile encode_textured_gltf(const reflectance::TriangleMesh& mesh, const brdffit::TextureAtlas& atlas,
                              const PngTextures& textures, ImageStorage storage, const std::string& image_stem);

}  // namespace fest::brdffit_tool

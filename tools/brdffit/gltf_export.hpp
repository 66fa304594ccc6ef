#pragma once
// glTF 2.0 export (specs/brdffit.md §2.10 `export`): the mesh with one primitive per
// material and a metallic-roughness approximation of each Lafortune BRDF -- baseColor =
// rho_d, roughness = sqrt(2 / (N + 2)) of the dominant lobe (the one with the largest
// peak), metallic 0 -- for viewers that know only PBR materials. One self-contained
// .gltf file: the binary buffer is embedded as a base64 data URI.

#include <string>

#include "reflectance/render.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit_tool {

// Materials per triangle (vertex weights: the largest weight of the triangle's first vertex).
std::string encode_gltf(const reflectance::TriangleMesh& mesh, const reflectance::SurfaceMaterials& materials);

// The roughness given to a Lafortune BRDF: sqrt(2 / (N + 2)) of the lobe with the
// largest peak value (mean over channels); 1 without lobes.
double gltf_roughness(const reflectance::LafortuneBrdf& brdf);

}  // namespace fest::brdffit_tool

#pragma once
// The metallic-roughness approximation of Lafortune BRDFs for glTF viewers (docs/brdffit.md
// §6, `export`): baseColor = rho_d, roughness = sqrt(2 / (N + 2)) of the dominant lobe of
// the dominant basis BRDF, metallic = 0.
//
// Why this is an approximation: a one-lobe Lafortune BRDF with Cxy = -Cz is a Phong lobe
// cos^N around the mirror direction; Walter et al. (EGSR 2007) match Phong's exponent to a
// Beckmann microfacet width by alpha^2 = 2 / (N + 2), and fest hands that alpha to glTF
// as its roughness (glTF squares its roughness into alpha, so the viewer's highlight is
// somewhat sharper than the fitted lobe). The lobe's colour and magnitude (|C|^N) are not
// carried: glTF dielectrics reflect F0 = 0.04 white; off-specular (|Cxy| != |Cz|) and
// retro-reflective (Cxy > 0) lobes are drawn as ordinary specular ones. metallic = 0
// because the Lafortune fit separates a diffuse albedo, which metals do not have.
//
// The surfaces below give baking (texture_bake.hpp) the value at any surface point:
// - from a materials file (per-triangle materials, or per-vertex blend weights), and
// - from the fitted result: the lumitexel nearest to the point on its triangle (the
//   renderer's rule of docs/brdffit.md §6) with its cluster's basis BRDFs and weights, plus the
//   refined normal of that lumitexel when given.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "brdffit/lumitexel.hpp"
#include "brdffit/project.hpp"
#include "brdffit/texture_bake.hpp"
#include "reflectance/lafortune.hpp"
#include "reflectance/render.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit {

// sqrt(2 / (N + 2)) of the lobe with the largest peak (|C|^N, channel means); 1 without lobes.
double pbr_roughness(const reflectance::LafortuneBrdf& brdf);

// A blend sum_j t_j f_j: base colour sum_j t_j rho_d,j (per channel; exact, the diffuse
// term is linear in the weights), roughness of the f_j with the largest |t_j| (docs/brdffit.md §6), i.e. of
// the dominant basis BRDF. `weights` holds one weight per BRDF, or 3 per BRDF
// channel-major (3 x count) when rgb.
PbrPoint pbr_of_blend(const std::vector<const reflectance::LafortuneBrdf*>& brdfs, const float* weights, bool rgb);
// The same with each BRDF's pbr_roughness given (baking evaluates millions of texels).
PbrPoint pbr_of_blend(const std::vector<const reflectance::LafortuneBrdf*>& brdfs, const std::vector<double>& roughness,
                      const float* weights, bool rgb);

// Surface of a materials file: vertex weights are blended barycentrically, else each
// triangle has its material. Throws bad_input on sizes that do not match the mesh.
PbrSurface materials_surface(const reflectance::TriangleMesh& mesh, const reflectance::SurfaceMaterials& materials);

// Surface of a projection: each point takes the lumitexel of its triangle nearest in
// space; triangles without a lumitexel take `fallback` (materials_from_projection's
// majority cluster BRDF). refined_normals: empty, or one world normal per lumitexel
// (brdffit normals). The returned function keeps references to its arguments.
class LumitexelSurface {
 public:
  LumitexelSurface(const reflectance::TriangleMesh& mesh, const LumitexelSet& set, const Projection& projection,
                   const reflectance::SurfaceMaterials& fallback, std::vector<Eigen::Vector3d> refined_normals = {});
  PbrPoint operator()(std::uint32_t triangle, const Eigen::Vector3d& bary) const;

 private:
  const reflectance::TriangleMesh& mesh_;
  const LumitexelSet& set_;
  const Projection& projection_;
  const reflectance::SurfaceMaterials& fallback_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<reflectance::LafortuneBrdf> basis_;
  std::vector<double> roughness_;  // pbr_roughness of each basis BRDF
  std::vector<std::uint32_t> order_, first_;  // lumitexels sorted by triangle; first_[t]..first_[t+1]
};

}  // namespace fest::brdffit

#pragma once
// Ground-truth scenes for brdffit (brdffit(1) `synth`, docs/brdffit.md §7): a mesh split into
// material patches, a turntable with a fixed camera and fixed point lights (docs/capture.md
// §1), rendered images and everything needed to check a reconstruction.

#include <cstdint>
#include <vector>

#include "brdffit/lumitexel_builder.hpp"
#include "reflectance/lafortune.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit {

// An icosahedron subdivided `level` times, projected to a sphere (20 * 4^level triangles),
// with exact normals (the radial direction).
reflectance::TriangleMesh icosphere(int level, double radius);

// A Phong-like Lafortune lobe around the mirror direction (Cxy = -Cz) whose peak value is
// rho_s (N + 2) / (2 pi) -- the normalised Phong lobe's.
reflectance::LafortuneLobe mirror_lobe(const reflectance::Rgb& rho_s, double exponent);

// Distinct materials for tests and demos: red plastic, blue matte, gold metal, green
// satin, white clay (one lobe each), then pbrt's measured clay (3 lobes); cycles beyond.
std::vector<reflectance::LafortuneBrdf> palette(int count);

// Splits the surface into `count` patches: `count` seed vertices chosen by farthest-point
// sampling from vertex `seed % V`, each triangle to the seed nearest its centroid.
std::vector<std::uint16_t> material_patches(const reflectance::TriangleMesh& mesh, int count, std::uint64_t seed);

// Tilts every vertex normal by a random angle up to `max_degrees` in a random direction
// (for normal refinement: the true normals stay in the ground truth).
void perturb_normals(reflectance::TriangleMesh& mesh, double max_degrees, std::uint64_t seed);

struct TurntableSetup {
  int views = 12;
  int lights = 1;
  int width = 640, height = 480;
  double elevation_deg = 25;   // camera above the table plane, seen from the object centre
  double distance = 3;         // camera distance in bounding-sphere radii
  double fill = 0.8;           // fraction of min(width, height) the bounding sphere spans
  double light_intensity = 0;  // 0: chosen so that a white diffuse surface facing the light reads about 1
};

struct TurntableImage {
  ImageView view;        // pose and light in the mesh frame
  int angle_index = 0;
  double angle_deg = 0;
  int light = 0;
};

// Views x lights images: the object turns about the vertical (z) axis through its
// bounding-sphere centre in steps of 360 / views degrees; camera and lights stay put
// (lights at fixed offsets from the camera, above and to the sides).
std::vector<TurntableImage> turntable_images(const reflectance::TriangleMesh& mesh, const TurntableSetup& setup);

}  // namespace fest::brdffit

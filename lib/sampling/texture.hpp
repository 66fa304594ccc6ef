#pragma once
// Texture minification (docs/resample.md "Mip-mapping", §10.3.2, §10.6): a mip pyramid and the lookups that
// filter it for a screen pixel's footprint -- nearest, bilinear, trilinear, hardware-style
// anisotropic probes and EWA -- plus the dense supersampled ground truth they approximate.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sampling/float_image.hpp"

namespace fest::sampling {

struct MipPyramid {
  std::vector<FloatImage> levels;  // level 0 = the texture (linear values)
};

// The kernel that halves each level of a pyramid.
enum class PyramidFilter { box, gaussian, lanczos3 };
// Its kernel spelling (make_kernel): box, gaussian:sigma=0.5, lanczos3.
const char* pyramid_kernel(PyramidFilter filter);

// Levels down to 1×1, each a 2× reduction of the previous one with `filter`. The texture
// tiles: edges wrap.
MipPyramid build_pyramid(const FloatImage& texture, PyramidFilter filter, int threads = 0);

// Texture coordinates of a screen point in level-0 texel units; `visible` false where
// nothing is hit (e.g. above the horizon).
struct TexCoord {
  double u = 0, v = 0;
  bool visible = false;
};
using TextureMap = std::function<TexCoord(double x, double y)>;

// The analytic ground plane z = 0 seen by a pinhole camera at height h, pitched down by
// `pitch` degrees, with vertical field of view `fov` degrees, for a screen of W×H pixels;
// the texture (tw×th texels) repeats every `period` world units.
TextureMap plane_map(double h, double pitch, double fov, double period, int width, int height, int tw, int th);

// A per-pixel table of (u, v) in [0, 1] (2 channels), read at pixel centres with bilinear
// interpolation between them; coordinates scaled to texels of a tw×th texture.
TextureMap table_map(const FloatImage& uv, int tw, int th);

enum class TexMethod { nearest, bilinear, trilinear, aniso, ewa };

struct TextureOptions {
  TexMethod method = TexMethod::trilinear;
  int max_aniso = 16;      // aniso:N, ewa:maxaniso=N
  bool aniso_gauss = false;  // aniso:N:gauss -- Gaussian instead of equal probe weights
  double lod_bias = 0;
  int threads = 0;
};

// "nearest", "bilinear", "trilinear", "aniso:N[:gauss]", "ewa[:maxaniso=16]".
TextureOptions parse_texture_method(const std::string& spec);

// The screen image W×H; the Jacobian of each pixel comes from central differences of the
// map (half a pixel either side). Invisible pixels are 0.5 (grey, as the checker-plane scene).
FloatImage texture_screen(const MipPyramid& pyr, const TextureMap& map, int width, int height, const TextureOptions& o);

// Dense ground truth: per pixel, jittered screen samples weighted by the σ = ½-pixel
// Gaussian, the exact map, bilinear level-0 lookups; N ≥ 1024, grown to ≥ 4 samples per
// covered texel, at most 65536.
FloatImage texture_ground_truth(const FloatImage& texture, const TextureMap& map, int width, int height, std::uint64_t seed,
                                int threads = 0);

// The footprint anisotropy |major| / |minor| of each pixel's Jacobian (0 where invisible).
FloatImage footprint_anisotropy(const TextureMap& map, int width, int height);

}  // namespace fest::sampling

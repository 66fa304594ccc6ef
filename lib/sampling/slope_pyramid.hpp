#pragma once
// Roughness-preserving slope pyramid (docs/resample.md "Roughness-preserving normal pyramid", [Sch97]): instead of averaging
// normals, which forgets the bumps that a coarse level can no longer show, each level
// keeps the first and second moments of the surface slopes s = (−n_x/n_z, −n_y/n_z):
// M₁ = E[s], M₂ = E[s sᵀ]. Moments average exactly under the box pyramid; per level the
// mean normal is ∝ (−M₁x, −M₁y, 1) and the slope covariance Σ = M₂ − M₁M₁ᵀ.

#include <vector>

#include "sampling/float_image.hpp"

namespace fest::sampling {

// Slopes (2 channels) from a height map (channel 0) times `scale`, by central differences
// with the map taken as periodic (textures tile; a map holding whole periods stays exact).
FloatImage slopes_from_height(const FloatImage& height, double scale);

// Slopes from a normal map (3 channels n; n_z ≤ 0 is bad input).
FloatImage slopes_from_normals(const FloatImage& normals);

struct SlopeLevel {
  FloatImage normal;      // 3 channels: the unit mean normal
  FloatImage covariance;  // 3 channels: Σ_xx, Σ_xy, Σ_yy
};

// Levels 0 (full size) down to 1×1, each half the previous size (odd sizes through the box
// weights). `naive`: average the unit normals and renormalise, Σ = 0 (what ordinary mip
// maps of normal maps do; for comparison).
std::vector<SlopeLevel> slope_pyramid(const FloatImage& slopes, bool naive, int threads = 0);

}  // namespace fest::sampling

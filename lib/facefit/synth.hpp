#pragma once
// The synthetic face population G2 (docs/facefit.md §4): an R×R grid over
// (u, w) ∈ [−1, 1]², x = W u, y = H w, depth D √max(0, 1 − u² − 0.8 w²) plus facial
// features whose centres, widths and heights follow 14 latent parameters θ ~ N(0, I)
// through smooth nonlinear maps, plus an individual detail field of 24 random bumps that move vertices in x, y and z.
// Nonlinear feature motion and individual detail keep novel faces outside the span of
// any finite training set, which is what makes the chapter's error-vs-η curve U-shaped.
// Vertex order is grid order: every face is in dense correspondence with every other.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/face_model.hpp"
#include "facefit/rng.hpp"

namespace fest::facefit {

struct DetailBump {
  double x = 0, y = 0, width = 0, height = 0;  // mm; height moves along z
  double shift_x = 0, shift_y = 0;               // mm; moves in the image plane
};

struct FaceParameters {
  std::array<double, 14> theta{};        // latent shape parameters, N(0, 1)
  std::vector<DetailBump> detail;        // individual detail
};

// Draws one face's parameters (θ, then 24 detail bumps, amplitudes N(0, detail_mm²) per axis).
FaceParameters draw_face(Rng& rng, double detail_mm);

// Vertex positions (3R² values, interleaved) of the face on an R×R grid.
Eigen::VectorXd face_shape(const FaceParameters& face, int resolution);

// Two triangles per grid cell, consistently oriented (normals towards +z, the viewer).
std::vector<std::array<std::uint32_t, 3>> grid_triangles(int resolution);

using face::NamedVertex;  // core/face_model.hpp

struct SynthLandmarks {
  std::vector<NamedVertex> set17;    // eye/mouth corners, brow ends, nose, lips, chin
  std::vector<NamedVertex> set50;    // set17 + brows, eyelids, bridge, lips, jaw
  std::vector<NamedVertex> set1000;  // seeded random vertices inside the evaluation mask
  std::vector<std::uint32_t> eval_mask;  // all but the top 15 % (forehead) and bottom 10 % (neck)
};

// Grid vertices nearest to the feature positions of the mean-parameter face (θ = 0),
// the same for all faces; distinct vertices in every set.
SynthLandmarks synth_landmarks(int resolution, std::uint64_t seed);

}  // namespace fest::facefit

#pragma once
// Error measures of the chapter (docs/facefit.md §3, eq. 51) and its experiment loop (docs/facefit.md §3, `sweep`).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "facefit/model.hpp"
#include "facefit/rng.hpp"

namespace fest::facefit {

// Per-vertex Euclidean distances between two shapes (interleaved, same length).
std::vector<double> vertex_errors(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int dims);

// E_full (eq. 51): mean per-vertex distance over `mask` (empty = all vertices).
double mean_error(const std::vector<double>& errors, const std::vector<std::uint32_t>& mask);

struct SweepSetting {
  std::size_t components = 0;  // k (≤ model components)
  double sigma_noise = 0;      // px, Gaussian noise per image coordinate
  double yaw_deg = 0;          // rotation of the solver's L about the vertical axis (fig. 1.6)
};

struct SweepRow {
  std::size_t face = 0;
  SweepSetting setting;
  std::size_t f = 0;
  double eta = 0;
  double E_r = 0, E_r_rms = 0, norm_c = 0, E_full = 0;
};

// The paper's protocol: project each true face frontally (1 px per model unit, centre
// (150, 150)), add noise, solve with the known camera (rotated by yaw_deg for the
// wrong-L experiment, no nuisance columns), one SVD per face and setting, every η.
// Noise draws come from `rng` in face order, so runs are reproducible.
std::vector<SweepRow> sweep(const Model& model, const std::vector<Eigen::VectorXd>& faces,
                            const std::vector<std::uint32_t>& vertices, const std::vector<double>& etas,
                            const std::vector<SweepSetting>& settings, const std::vector<std::uint32_t>& mask,
                            std::uint64_t seed);

}  // namespace fest::facefit

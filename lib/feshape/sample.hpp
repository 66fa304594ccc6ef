#pragma once
// Synthetic data: points on a deformable superquadric (eqs. 1-3), optionally with smooth
// radial bumps (a stand-in for the seed's "deforming superquadric" local shape) and
// Gaussian noise. Deterministic for a seed (lib/core's portable generator).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "feshape/model.hpp"

namespace fest::feshape {

struct SampleOptions {
  std::size_t count = 2000;
  double noise = 0;         // standard deviation of isotropic Gaussian noise (absolute)
  int bumps = 0;            // number of Gaussian bumps along the radial direction
  double bump_amplitude = 0;  // relative to a
  std::uint64_t seed = 1;
};

// (u, v) are drawn uniformly on the unit sphere (u = asin(2r - 1)), mapped through
// x = c + R (s(u, v) + bump(u, v) s/|s|) + noise.
std::vector<Eigen::Vector3d> sample_points(const Model& model, const SampleOptions& o);

}  // namespace fest::feshape

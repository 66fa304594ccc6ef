#pragma once
// A radiance sample reduced to what an isotropic BRDF fit needs (docs/brdffit.md §3:
// the clusterer keeps samples in local-frame f32 form, 28 bytes each): the two
// products the Lafortune base is made of, the cosine u_z the radiance is multiplied by,
// the normalised radiance r = f_r u_z per channel and the sample's weight.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "brdffit/lumitexel.hpp"

namespace fest::brdffit {

struct FitSample {
  float xy = 0;  // u_x v_x + u_y v_y (local frame)
  float z = 0;   // u_z v_z
  float uz = 0;  // cos theta_i
  float r[3] = {0, 0, 0};
  float w = 1;
};
static_assert(sizeof(FitSample) == 28, "FitSample is the 28-byte record of docs/brdffit.md §3");

// Local directions u, v (unit, z = normal) to a fit sample.
FitSample make_fit_sample(const Eigen::Vector3d& u_local, const Eigen::Vector3d& v_local,
                          const Eigen::Vector3d& r, double weight = 1);

// Every sample of every lumitexel in the lumitexel's own local frame (reflectance::
// local_frame of its normal), in the same order as set.samples.
std::vector<FitSample> local_samples(const LumitexelSet& set, int threads);

// The samples of lumitexel i in the frame of the unit normal n (normal refinement).
void local_samples_of(const LumitexelSet& set, std::size_t i, const Eigen::Vector3d& n, std::vector<FitSample>& out);

}  // namespace fest::brdffit

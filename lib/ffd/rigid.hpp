#pragma once
// Rigid attachment (seed section 16: bones move rigidly inside a deforming lattice;
// docs/ffd.md 2.4): the rotation R and translation t minimising
// sum_v a_v |R X_v + t - X'_v|^2 (Kabsch/Umeyama without scale, with the reflection fix).

#include <vector>

#include <Eigen/Core>

namespace fest::ffd {

struct RigidFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rms = 0;  // weighted RMS of R X + t - X' (how non-rigid the target motion is)
};

// `weights` may be empty (all 1). Throws fest::Error(bad_input) for sizes that differ or
// no positive weight.
RigidFit fit_rigid(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                   const std::vector<double>& weights = {});

}  // namespace fest::ffd

#include "ffd/rigid.hpp"

#include <cmath>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/error.hpp"

namespace fest::ffd {

RigidFit fit_rigid(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                   const std::vector<double>& weights) {
  if (from.size() != to.size() || (!weights.empty() && weights.size() != from.size()))
    throw bad_input("rigid fit: point counts differ");
  double wsum = 0;
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    wsum += w;
    ca += w * from[i];
    cb += w * to[i];
  }
  if (!(wsum > 0)) throw bad_input("rigid fit: no points with positive weight");
  ca /= wsum;
  cb /= wsum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    H += w * (from[i] - ca) * (to[i] - cb).transpose();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0) D(2, 2) = -1;
  RigidFit fit;
  fit.rotation = svd.matrixV() * D * svd.matrixU().transpose();
  fit.translation = cb - fit.rotation * ca;
  double e = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    e += w * (fit.rotation * from[i] + fit.translation - to[i]).squaredNorm();
  }
  fit.rms = std::sqrt(e / wsum);
  return fit;
}

}  // namespace fest::ffd

#include "facefit/camera.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/error.hpp"

namespace fest::facefit {

namespace {
constexpr double deg = M_PI / 180.0;
}

CameraMatrix orthographic_camera(double scale, const Eigen::Vector2d& center, double yaw_deg, double pitch_deg) {
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(pitch_deg * deg, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(yaw_deg * deg, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  CameraMatrix P;
  P.block<1, 3>(0, 0) = scale * R.row(0);
  P.block<1, 3>(1, 0) = -scale * R.row(1);  // image v points down, model y up
  P(0, 3) = center.x();
  P(1, 3) = center.y();
  return P;
}

Eigen::Matrix2Xd project_points(const CameraMatrix& P, const Eigen::Matrix3Xd& points) {
  return (P.leftCols<3>() * points).colwise() + P.col(3);
}

CameraMatrix fit_similarity(const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& image, const Eigen::VectorXd& w) {
  const Eigen::Index f = points.cols();
  const Eigen::VectorXd wt = w.size() == f ? w : Eigen::VectorXd::Ones(f);
  const double W = wt.sum();
  const Eigen::Vector2d mx = (points.topRows<2>() * wt) / W;
  const Eigen::Vector2d mu = (image * wt) / W;
  double num = 0, den = 0;
  for (Eigen::Index a = 0; a < f; ++a) {
    const double x = points(0, a) - mx.x(), y = points(1, a) - mx.y();
    const double u = image(0, a) - mu.x(), v = image(1, a) - mu.y();
    num += wt(a) * (x * u - y * v);
    den += wt(a) * (x * x + y * y);
  }
  const double s = den > 0 ? num / den : 0.0;
  CameraMatrix P = CameraMatrix::Zero();
  P(0, 0) = s;
  P(1, 1) = -s;
  P(0, 3) = mu.x() - s * mx.x();
  P(1, 3) = mu.y() + s * mx.y();
  return P;
}

CameraMatrix fit_scaled_orthographic(const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& image, const Eigen::VectorXd& w) {
  const Eigen::Index f = points.cols();
  if (f < 4) throw runtime_failure("the affine camera needs at least 4 landmarks, got {}", f);
  const Eigen::VectorXd wt = w.size() == f ? w : Eigen::VectorXd::Ones(f);
  const Eigen::Vector2d centroid = image.rowwise().mean();
  if ((image.colwise() - centroid).cwiseAbs().maxCoeff() <= 1e-9 * std::max(1.0, centroid.cwiseAbs().maxCoeff()))
    throw runtime_failure("degenerate affine camera: all landmarks lie on one image point");
  Eigen::MatrixXd A(f, 4);
  Eigen::MatrixXd B(f, 2);
  for (Eigen::Index a = 0; a < f; ++a) {
    A.row(a) << points(0, a), points(1, a), points(2, a), 1.0;
    A.row(a) *= wt(a);
    B.row(a) = wt(a) * image.col(a).transpose();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svdA(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svdA.singularValues();
  if (!(sv(3) > 1e-9 * sv(0))) throw runtime_failure("degenerate affine camera: the landmarks' 3-D positions are coplanar or coincide");
  const Eigen::MatrixXd X = svdA.solve(B);  // 4×2
  const Eigen::Matrix<double, 2, 3> M = X.topRows<3>().transpose();
  Eigen::JacobiSVD<Eigen::Matrix<double, 2, 3>> svdM(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const double s = (svdM.singularValues()(0) + svdM.singularValues()(1)) / 2;
  if (!(s > 0)) throw runtime_failure("degenerate affine camera: all landmarks project to one point");
  const Eigen::Matrix<double, 2, 3> R2 = svdM.matrixU() * svdM.matrixV().leftCols<2>().transpose();
  CameraMatrix P;
  P.leftCols<3>() = s * R2;
  // Translation that best fits the rotated points (weighted centroids).
  const double W = wt.sum();
  const Eigen::Vector3d mx = (points * wt) / W;
  const Eigen::Vector2d mu = (image * wt) / W;
  P.col(3) = mu - s * R2 * mx;
  return P;
}

Eigen::VectorXd to_image_space(const CameraMatrix& P, const Eigen::VectorXd& shape) {
  const Eigen::Vector3d r0 = P.block<1, 3>(0, 0).transpose(), r1 = -P.block<1, 3>(1, 0).transpose();
  const double s = (r0.norm() + r1.norm()) / 2;
  const Eigen::Vector3d axis = r0.cross(r1).normalized() * s;
  Eigen::VectorXd out(shape.size());
  for (Eigen::Index j = 0; j + 2 < shape.size(); j += 3) {
    const Eigen::Vector3d x = shape.segment<3>(j);
    out.segment<2>(j) = P.leftCols<3>() * x + P.col(3);
    out(j + 2) = axis.dot(x);
  }
  return out;
}

CameraPose decompose_camera(const CameraMatrix& P) {
  CameraPose pose;
  const Eigen::Vector3d r0 = P.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d r1 = -P.block<1, 3>(1, 0).transpose();
  pose.scale = (r0.norm() + r1.norm()) / 2;
  const Eigen::Vector3d a = r0 / r0.norm(), b = r1 / r1.norm();
  // R = R_x(pitch) R_y(yaw): row 0 = (cos y, 0, sin y), row 1 = (sin p sin y, cos p, −sin p cos y).
  const double yaw = std::atan2(a.z(), a.x());
  const double sp = b.x() * std::sin(yaw) - b.z() * std::cos(yaw);
  pose.yaw_deg = yaw / deg;
  pose.pitch_deg = std::atan2(sp, b.y()) / deg;
  pose.translation = P.col(3);
  return pose;
}

}  // namespace fest::facefit

#pragma once
// Cameras of the fit (docs/facefit.md §3): a 2×4 matrix P maps a model point (x, y, z, 1) to
// image (u, v), u right and v down, model y up. Frontal scaled orthographic:
// P = [[s, 0, 0, t_u], [0, −s, 0, t_v]] (the paper's L); rotated views multiply the
// rotation R = R_x(pitch) R_y(yaw) in first.

#include <Eigen/Core>

namespace fest::facefit {

using CameraMatrix = Eigen::Matrix<double, 2, 4>;

// Scaled orthographic camera: scale s (px per model unit), image centre (t_u, t_v),
// yaw and pitch in degrees.
CameraMatrix orthographic_camera(double scale, const Eigen::Vector2d& center, double yaw_deg = 0, double pitch_deg = 0);

// Projects points (3×f) with P: 2×f.
Eigen::Matrix2Xd project_points(const CameraMatrix& P, const Eigen::Matrix3Xd& points);

// Least-squares frontal similarity u = s x + t_u, v = −s y + t_v from 3-D points to image
// points (the paper's translation + scale, eq. 49-50). Weighted by w (size f) if given.
CameraMatrix fit_similarity(const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& image, const Eigen::VectorXd& w);

// Least-squares affine camera (2×4) from ≥ 4 non-coplanar points, projected to the
// nearest scaled orthographic camera (M = U Σ V^T → s = (Σ11 + Σ22)/2, R2 = U V^T).
// Throws runtime_failure when the points are degenerate.
CameraMatrix fit_scaled_orthographic(const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& image, const Eigen::VectorXd& w);

// A shape (interleaved xyz) in image space: (u, v, depth) per vertex, u and v in pixels,
// depth = s·(r₀ × r₁)·x towards the viewer in pixels (the camera's third axis).
Eigen::VectorXd to_image_space(const CameraMatrix& P, const Eigen::VectorXd& shape);

// Scale and angles of a scaled orthographic camera built like orthographic_camera().
struct CameraPose {
  double scale = 0;
  double yaw_deg = 0;
  double pitch_deg = 0;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
};
CameraPose decompose_camera(const CameraMatrix& P);

}  // namespace fest::facefit

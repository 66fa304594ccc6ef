#include "capture/calib_camera.hpp"

#include <cmath>

#include <opencv2/calib3d.hpp>

#include "core/error.hpp"

namespace fest::capture {

namespace {

cv::Mat k_mat(const Intrinsics& c) { return cv::Mat(c.K, true); }
cv::Mat dist_mat(const Intrinsics& c) { return cv::Mat(c.dist, true).reshape(1, 1); }

Pose pose_of(const cv::Mat& rvec, const cv::Mat& tvec) {
  Pose p;
  cv::Mat R;
  cv::Rodrigues(rvec, R);
  p.R = cv::Matx33d(R);
  p.t = cv::Vec3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  return p;
}

}  // namespace

double reprojection_rms(const std::vector<cv::Point2f>& corners, const BoardSpec& board, const Intrinsics& camera,
                        const Pose& pose) {
  const std::vector<cv::Point3f> object = board_object_points(board);
  cv::Mat rvec;
  cv::Rodrigues(cv::Mat(pose.R), rvec);
  std::vector<cv::Point2f> projected;
  cv::projectPoints(object, rvec, cv::Mat(pose.t), k_mat(camera), dist_mat(camera), projected);
  double sum = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const cv::Point2f d = projected[i] - corners[i];
    sum += double(d.dot(d));
  }
  return corners.empty() ? 0 : std::sqrt(sum / double(corners.size()));
}

CameraCalibration calibrate_camera(const std::vector<std::vector<cv::Point2f>>& views, const BoardSpec& board,
                                   cv::Size image_size, const CameraCalibOptions& options) {
  if (views.size() < 3)
    throw bad_input("{} view{} with the whole board; camera calibration needs at least 3", views.size(),
                    views.size() == 1 ? "" : "s");
  const std::vector<cv::Point3f> object = board_object_points(board);
  const std::vector<std::vector<cv::Point3f>> objects(views.size(), object);
  int flags = 0;
  if (options.fix_k3) flags |= cv::CALIB_FIX_K3;
  if (options.zero_tangent) flags |= cv::CALIB_ZERO_TANGENT_DIST;
  cv::Mat K, dist;
  std::vector<cv::Mat> rvecs, tvecs;
  double rms = 0;
  try {
    rms = cv::calibrateCamera(objects, views, image_size, K, dist, rvecs, tvecs, flags,
                              cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-12));
  } catch (const cv::Exception& e) {
    throw runtime_failure("camera calibration failed: {}", e.err);
  }
  if (!std::isfinite(rms) || !cv::checkRange(K) || !cv::checkRange(dist))
    throw runtime_failure("camera calibration did not converge (reprojection error {})", rms);
  CameraCalibration result;
  result.intrinsics.K = cv::Matx33d(K);
  for (int i = 0; i < 5; ++i) result.intrinsics.dist[i] = i < int(dist.total()) ? dist.at<double>(i) : 0.0;
  result.intrinsics.width = image_size.width;
  result.intrinsics.height = image_size.height;
  result.rms = rms;
  for (std::size_t v = 0; v < views.size(); ++v) {
    result.poses.push_back(pose_of(rvecs[v], tvecs[v]));
    result.view_rms.push_back(reprojection_rms(views[v], board, result.intrinsics, result.poses.back()));
  }
  return result;
}

Pose board_pose(const std::vector<cv::Point2f>& corners, const BoardSpec& board, const Intrinsics& camera) {
  cv::Mat rvec, tvec;
  bool ok = false;
  try {
    ok = cv::solvePnP(board_object_points(board), corners, k_mat(camera), dist_mat(camera), rvec, tvec, false,
                      cv::SOLVEPNP_ITERATIVE);
  } catch (const cv::Exception& e) {
    throw runtime_failure("board pose: {}", e.err);
  }
  if (!ok) throw runtime_failure("board pose: solvePnP found no pose");
  return pose_of(rvec, tvec);
}

}  // namespace fest::capture

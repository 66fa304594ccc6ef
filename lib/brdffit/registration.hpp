#pragma once
// Silhouette-based registration of photographs to a mesh (docs/brdffit.md §6; chapter 8
// §8.6.2). Cost: the pixels covered by exactly one of the mesh's rendered silhouette and
// the photograph's mask, divided by the mask's pixel count, evaluated on an image pyramid
// (1/8, 1/4, 1/2, 1). Unknowns per image: rotation omega (axis-angle), translation t and
// log f (fx; fy keeps the calibrated aspect ratio). Downhill simplex at every level,
// restarted from the previous level's optimum. Turntable mode fits one camera and the
// table's axis to all silhouettes of a rig at once (7 + 4 parameters).

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "reflectance/camera.hpp"
#include "reflectance/silhouette_runs.hpp"
#include "reflectance/triangle_mesh.hpp"
#include "core/progress_callback.hpp"

namespace fest::brdffit {

// The mask at 1/8, 1/4, 1/2 and full resolution (area-averaged, foreground where >= 1/2).
struct SilhouettePyramid {
  std::vector<cv::Mat> masks;   // CV_8U 0/1, coarsest first
  std::vector<double> scales;   // 1/8 ... 1
  std::vector<double> counts;   // foreground pixels per level
  std::vector<reflectance::CoverageRuns> runs;  // the masks as runs per row, for the XOR
};
SilhouettePyramid make_pyramid(const cv::Mat& mask, int levels = 4);

// XOR(silhouette, mask) / |mask| at one level; `camera` is the full-resolution camera.
// Counted on runs per row (reflectance::silhouette_runs): the pixels of a filled
// silhouette image, found without filling one.
double silhouette_xor(const reflectance::TriangleMesh& mesh, const reflectance::PinholeCamera& camera,
                      const SilhouettePyramid& pyramid, std::size_t level, int threads = 1);

// 7 parameters (omega, t, log fx) <-> camera; the rest of `base` (cx, cy, fy/fx,
// distortion, size) is kept.
Eigen::VectorXd pose_parameters(const reflectance::PinholeCamera& camera);
reflectance::PinholeCamera camera_from_parameters(const reflectance::PinholeCamera& base, const Eigen::VectorXd& x);

struct RegistrationOptions {
  bool automatic = false;     // ignore the initial pose: search orientations (focal length kept)
  int orient_samples = 240;
  // The first choice of 20 coarse steps and 5 candidates found 6 of 10 bunny poses at 320x240;
  // 40 and 15 found 10 of 10 (tests/bench/brdffit_register_auto.sh) at about twice the time.
  int coarse_iters = 40;
  int keep = 15;              // candidates refined at every level
  int iters_per_level = 300;
  double rotation_step_deg = 5;
  double translation_step = 0.05;  // fraction of the camera distance
  double focal_step = 0.05;        // in log f
  bool fix_focal = false;          // f known from calibration: optimise the 6 pose parameters
  int restarts = 4;                // extra simplex restarts at full resolution while they gain
  std::uint64_t seed = 1;
  int threads = 1;
  ProgressFn progress;  // simplex runs done of those planned (restarts that stop early count as run)
};

struct RegistrationResult {
  reflectance::PinholeCamera camera;
  double xor_cost = 0;   // at full resolution
  long evaluations = 0;  // silhouettes rendered
};

RegistrationResult register_silhouette(const reflectance::TriangleMesh& mesh, const cv::Mat& mask,
                                       const reflectance::PinholeCamera& initial, const RegistrationOptions& options);

// Turntable mode: image k shows the object turned by angle_deg[k] about the table's axis.
// Camera k is R0 R_axis(theta_k), R0 (a - R_axis(theta_k) a) + t0 with one intrinsic set;
// the initial pose is taken from `initial` (one camera per image, as the rig gives them),
// the initial axis from `axis_direction` through `axis_point` (mesh frame).
struct TurntableFit {
  std::vector<reflectance::PinholeCamera> cameras;  // per image, mesh frame
  Eigen::Vector3d axis_direction = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();
  double xor_cost = 0;  // mean over the distinct masks, full resolution
  long evaluations = 0;
};

TurntableFit register_turntable(const reflectance::TriangleMesh& mesh, const std::vector<cv::Mat>& masks,
                                const std::vector<double>& angle_deg,
                                const std::vector<reflectance::PinholeCamera>& initial,
                                const Eigen::Vector3d& axis_direction, const Eigen::Vector3d& axis_point,
                                const RegistrationOptions& options);

// The turntable axis the cameras of a rig imply: image k's camera is R0 R_axis(dtheta_k),
// t0 + R0 (I - R_axis(dtheta_k)) a relative to image 0, so the axis direction is the
// rotation axis of R0^T R_k and the point a (the one closest to the origin) solves the
// stacked linear equations R0^T (t_k - t0) = (I - R_axis(dtheta_k)) a. Images at the
// angle of image 0 carry no information; with none at another angle, z through the
// origin is returned (hdrmerge's turntable frame).
void estimate_turntable_axis(const std::vector<reflectance::PinholeCamera>& cameras, const std::vector<double>& angle_deg,
                             Eigen::Vector3d& direction, Eigen::Vector3d& point);

// Uniformly distributed rotations (Shoemake's subgroup algorithm) from a seeded generator.
std::vector<Eigen::Matrix3d> random_rotations(int count, std::uint64_t seed);

}  // namespace fest::brdffit

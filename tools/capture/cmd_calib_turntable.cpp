// capture calib-turntable (docs/capture.md §5): turntable axis and centre from a board lying on
// the table at known angles (lib/capture/calib_turntable) -> turntable_cal.json on stdout.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calib_images.hpp"
#include "capture/calib_board.hpp"
#include "capture/calib_turntable.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace fest::capture_tool {

using nlohmann::json;
using namespace fest::capture;

namespace {

// The commanded turntable angle of every image: the list given, or N equal steps over a
// revolution in image order (N = the count given, or the number of images).
std::vector<double> angles_of_images(const CalibTurntableOptions& a, std::size_t images) {
  std::vector<double> angles = a.angles_deg;
  if (angles.empty()) {
    const int n = a.angle_count > 0 ? a.angle_count : int(images);
    for (int k = 0; k < n; ++k) angles.push_back(360.0 * k / n);
  }
  if (angles.size() != images)
    throw bad_input("{} turntable angles for {} images: one angle per image, in order", angles.size(), images);
  return angles;
}

}  // namespace

int calib_turntable_command(const CalibTurntableOptions& a) {
  const BoardSpec& board = a.board;
  if (!board_has_orientation(board))
    throw usage_error("board {}x{}: a turntable needs inner corner counts of different parity (9x6, 7x4), so that "
                      "a half turn of the board can be told apart",
                      board.cols, board.rows);
  const Intrinsics cam = read_camera(a.camera);
  const std::vector<double> all_angles = angles_of_images(a, a.images.size());
  const BoardViews v = find_boards(a.images, board, a.quiet, [&](const cv::Mat& m, const std::string& path) {
    check_camera_size(cam, m, a.camera, path);
  });
  std::vector<double> angles;
  std::vector<Pose> poses;
  std::vector<double> reprojection;
  for (std::size_t i = 0, u = 0; i < a.images.size() && u < v.used.size(); ++i) {
    if (a.images[i] != v.used[u]) continue;
    angles.push_back(all_angles[i]);
    poses.push_back(board_pose(v.corners[u], board, cam));
    reprojection.push_back(reprojection_rms(v.corners[u], board, cam, poses.back()));
    ++u;
  }
  const TurntableCalibration cal = calibrate_turntable(poses, angles, board);
  json views = json::array();
  for (std::size_t k = 0; k < poses.size(); ++k)
    views.push_back({{"image", v.used[k]},
                     {"commanded_deg", angles[k]},
                     {"measured_deg", cal.measured_deg[k]},
                     {"residual_deg", cal.angle_residual_deg[k]},
                     {"circle_rms_mm", cal.circle_rms_mm[k]},
                     {"height_rms_mm", cal.height_rms_mm[k]},
                     {"reprojection_rms_px", reprojection[k]}});
  emit_board_result({{"R_T0", json_array(cal.R_T0)},
                     {"t_T0", json_array(cal.t_T0)},
                     {"axis", json_array(cal.axis)},
                     {"axis_spread_deg", cal.axis_spread_deg},
                     {"angle_rms_deg", cal.angle_rms_deg},
                     {"camera", a.camera}},
                    a.board_name, views, v);
  return 0;
}

}  // namespace fest::capture_tool

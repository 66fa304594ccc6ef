// capture calib-camera (docs/capture.md §5): camera intrinsics from chessboard images
// (lib/capture/calib_camera) -> camera.json (K, dist, RMS; brdffit's cam.json) on stdout.

#include <string>

#include <nlohmann/json.hpp>

#include "calib_images.hpp"
#include "capture/calib_board.hpp"
#include "capture/calib_camera.hpp"
#include "commands.hpp"

namespace fest::capture_tool {

using nlohmann::json;
using namespace fest::capture;

int calib_camera_command(const CalibCameraOptions& a) {
  const BoardSpec& board = a.board;
  const BoardViews v = find_boards(a.images, board, a.quiet);
  CameraCalibOptions options;
  options.fix_k3 = a.fix_k3;
  options.zero_tangent = a.zero_tangent;
  const CameraCalibration cal = calibrate_camera(v.corners, board, v.size, options);
  const Intrinsics& k = cal.intrinsics;
  json views = json::array();
  for (std::size_t i = 0; i < v.used.size(); ++i) views.push_back({{"image", v.used[i]}, {"rms_px", cal.view_rms[i]}});
  emit_board_result({{"K", json_array(k.K)},
                     {"dist", json_array(k.dist)},
                     {"R", json_array(cv::Matx33d::eye())},
                     {"t", json::array({0, 0, 0})},
                     {"width", k.width},
                     {"height", k.height},
                     {"rms", cal.rms}},
                    a.board_name, views, v);
  return 0;
}

}  // namespace fest::capture_tool

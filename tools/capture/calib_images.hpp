#pragma once
// What the calibration subcommands share (docs/capture.md §5): board and sphere images
// read as grey, the camera.json of calib-camera read back, chessboards found in a list
// of images, and the JSON written on standard output.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"
#include "capture/calib_camera.hpp"

namespace fest::capture_tool {

// "capture: warning: message" unless quiet.
void note(bool quiet, const std::string& message);

// One image as grey: float 0..1 and 8-bit (for the corner detector).
struct GreyImage {
  cv::Mat grey;
  cv::Mat grey8;
};
GreyImage read_grey(const std::string& path);

// "a, b, c".
std::string joined(const std::vector<std::string>& names);

// Matrices and vectors as flat JSON arrays (row-major).
nlohmann::json json_array(const cv::Matx33d& m);
template <int N>
nlohmann::json json_array(const cv::Vec<double, N>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < N; ++i) a.push_back(v[i]);
  return a;
}

// The camera.json that calib-camera writes (brdffit's cam.json fields).
capture::Intrinsics read_camera(const std::string& path);

// Refuses an image not of the calibrated camera's size.
void check_camera_size(const capture::Intrinsics& cam, const cv::Mat& m, const std::string& camera_path,
                       const std::string& path);

// Corners of every image that shows the whole board; images without one are named (a
// note each, unless quiet). `check` sees every image first.
struct BoardViews {
  std::vector<std::string> used, missing;
  std::vector<std::vector<cv::Point2f>> corners;
  cv::Size size;
};
BoardViews find_boards(const std::vector<std::string>& images, const capture::BoardSpec& board, bool quiet,
                       const std::function<void(const cv::Mat&, const std::string&)>& check = {});

// A board calibration's result on standard output: `doc` with the board as given, the
// per-view report and the images left out.
void emit_board_result(nlohmann::json doc, const std::string& board_name, const nlohmann::json& views,
                       const BoardViews& found);

// Any result on standard output.
void emit(const nlohmann::json& doc);

}  // namespace fest::capture_tool

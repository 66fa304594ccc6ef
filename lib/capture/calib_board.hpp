#pragma once
// What the three calibrations (docs/capture.md §5) share: the chessboard, the
// camera intrinsics and rigid poses, in the camera frame C of docs/capture.md §1 with lengths in the
// unit of the board's squares (millimetres by convention).

#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

namespace fest::capture {

// A chessboard by its inner corners (OpenCV's pattern size) and square size.
struct BoardSpec {
  int cols = 9;         // inner corners per row
  int rows = 6;         // rows of inner corners
  double square = 25;   // side of one square, mm
};

// "9x6x25mm", "9x6x25" (mm implied) or "9x6x0.025m". Throws fest::Error (usage).
BoardSpec parse_board_spec(std::string_view text);

// Inner corners in the board frame: z = 0, x along a row, y across rows, in the order
// find_board_corners returns them.
std::vector<cv::Point3f> board_object_points(const BoardSpec& board);

// Pinhole camera with OpenCV's 5-coefficient distortion (k1, k2, p1, p2, k3).
struct Intrinsics {
  cv::Matx33d K = cv::Matx33d::eye();
  cv::Vec<double, 5> dist = cv::Vec<double, 5>::all(0);
  int width = 0, height = 0;
};

// X_C = R X + t.
struct Pose {
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d t = cv::Vec3d(0, 0, 0);
};

// Any fest image (8/16-bit or float, 1-4 channels, RGB order) as 8-bit grey for the
// corner detector; floats are taken as 0..1.
cv::Mat to_gray8(const cv::Mat& pixels);
// The same as floating-point grey 0..1 (16-bit data keeps its precision).
cv::Mat to_gray_float(const cv::Mat& pixels);

// The board's inner corners refined to sub-pixel accuracy, or an empty vector when the
// whole board is not seen. Boards whose corner counts have different parity (9x6) are
// put in one canonical order -- the cell between corners 0, 1, cols, cols+1 is dark --
// so that a board turned by half a revolution keeps its frame (the turntable needs it);
// OpenCV alone may number such a board from either end.
std::vector<cv::Point2f> find_board_corners(const cv::Mat& gray8, const BoardSpec& board);

// Whether find_board_corners can tell a half turn of this board (cols + rows odd).
bool board_has_orientation(const BoardSpec& board);

}  // namespace fest::capture

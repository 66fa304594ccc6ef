#include "capture/calib_board.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fest::capture {

BoardSpec parse_board_spec(std::string_view text) {
  const std::string s(text);
  int cols = 0, rows = 0, used = 0;
  double square = 0;
  char unit[4] = {0, 0, 0, 0};
  const int n = std::sscanf(s.c_str(), "%dx%dx%lf%n%3s", &cols, &rows, &square, &used, unit);
  const std::string suffix = n >= 3 ? s.substr(std::size_t(used)) : std::string();
  double scale = 0;
  if (suffix.empty() || suffix == "mm") scale = 1;
  else if (suffix == "cm") scale = 10;
  else if (suffix == "m") scale = 1000;
  if (n < 3 || scale == 0 || cols < 2 || rows < 2 || !(square > 0) || !std::isfinite(square) || cols > 200 || rows > 200)
    throw usage_error("board '{}': expected COLSxROWSxSIZE[mm|cm|m] with at least 2x2 inner corners, e.g. 9x6x25mm", s);
  if (cols == rows)
    throw usage_error("board '{}': a square pattern of inner corners is ambiguous under a quarter turn; use one like 9x6", s);
  return BoardSpec{cols, rows, square * scale};
}

std::vector<cv::Point3f> board_object_points(const BoardSpec& board) {
  std::vector<cv::Point3f> points;
  points.reserve(std::size_t(board.cols * board.rows));
  for (int r = 0; r < board.rows; ++r)
    for (int c = 0; c < board.cols; ++c)
      points.emplace_back(float(c * board.square), float(r * board.square), 0.f);
  return points;
}

namespace {

cv::Mat grey_of(const cv::Mat& pixels) {
  const int ch = pixels.channels();
  if (ch == 1) return pixels;
  cv::Mat rgb = pixels;
  if (ch == 2 || ch == 4) {  // drop alpha: it is not light
    std::vector<cv::Mat> planes;
    cv::split(pixels, planes);
    planes.pop_back();
    cv::merge(planes, rgb);
  }
  if (rgb.channels() == 1) return rgb;
  cv::Mat grey;
  cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
  return grey;
}

}  // namespace

cv::Mat to_gray_float(const cv::Mat& pixels) {
  const cv::Mat grey = grey_of(pixels);
  cv::Mat out;
  const double scale = grey.depth() == CV_8U ? 1.0 / 255 : grey.depth() == CV_16U ? 1.0 / 65535 : 1.0;
  grey.convertTo(out, CV_32F, scale);
  return out;
}

cv::Mat to_gray8(const cv::Mat& pixels) {
  const cv::Mat grey = grey_of(pixels);
  if (grey.depth() == CV_8U) return grey;
  cv::Mat out;
  const double scale = grey.depth() == CV_16U ? 255.0 / 65535 : 255.0;
  grey.convertTo(out, CV_8U, scale);  // saturating
  return out;
}

bool board_has_orientation(const BoardSpec& board) { return (board.cols + board.rows) % 2 == 1; }

namespace {

// Mean grey inside the quadrilateral of four corners (a shrunken copy, so that
// blurred edges do not leak in).
double cell_mean(const cv::Mat& gray8, const cv::Point2f q[4]) {
  const cv::Point2f centre = (q[0] + q[1] + q[2] + q[3]) * 0.25f;
  std::vector<cv::Point> poly;
  for (int i = 0; i < 4; ++i) {
    const cv::Point2f p = centre + (q[i] - centre) * 0.5f;
    poly.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
  }
  cv::Mat mask = cv::Mat::zeros(gray8.size(), CV_8U);
  cv::fillConvexPoly(mask, poly, cv::Scalar(255));
  return cv::mean(gray8, mask)[0];
}

// Smallest distance between neighbouring corners: bounds cornerSubPix's window, which
// must stay inside one square.
double corner_spacing(const std::vector<cv::Point2f>& corners, const BoardSpec& board) {
  double spacing = 1e30;
  for (int r = 0; r < board.rows; ++r)
    for (int c = 0; c < board.cols; ++c) {
      const cv::Point2f p = corners[std::size_t(r * board.cols + c)];
      if (c + 1 < board.cols) spacing = std::min(spacing, double(cv::norm(corners[std::size_t(r * board.cols + c + 1)] - p)));
      if (r + 1 < board.rows) spacing = std::min(spacing, double(cv::norm(corners[std::size_t((r + 1) * board.cols + c)] - p)));
    }
  return spacing;
}

}  // namespace

std::vector<cv::Point2f> find_board_corners(const cv::Mat& gray8, const BoardSpec& board) {
  std::vector<cv::Point2f> corners;
  const cv::Size pattern(board.cols, board.rows);
  const bool found = cv::findChessboardCorners(gray8, pattern, corners,
                                               cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE);
  if (!found || corners.size() != std::size_t(board.cols * board.rows)) return {};
  // Half a square's spacing at most, 11x11 (OpenCV's usual) at best.
  const int half = std::clamp(int(corner_spacing(corners, board) * 0.4), 2, 5);
  cv::cornerSubPix(gray8, corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4));
  // One handedness: x along a row, y across rows, turning clockwise in the image as
  // the board frame does seen from the camera (its z axis points away from the camera).
  // A board is printed on one side only, so the mirrored numbering is never right.
  const std::size_t w = std::size_t(board.cols);
  const cv::Point2f along = corners[1] - corners[0], across = corners[w] - corners[0];
  if (along.x * across.y - along.y * across.x < 0)
    for (int r = 0; r < board.rows; ++r)
      std::reverse(corners.begin() + r * board.cols, corners.begin() + (r + 1) * board.cols);
  if (board_has_orientation(board)) {
    // Compare the first cell with its neighbour along the row: the first must be darker.
    const cv::Point2f first[4] = {corners[0], corners[1], corners[w + 1], corners[w]};
    const cv::Point2f next[4] = {corners[1], corners[2], corners[w + 2], corners[w + 1]};
    if (cell_mean(gray8, first) > cell_mean(gray8, next)) std::reverse(corners.begin(), corners.end());
  }
  return corners;
}

}  // namespace fest::capture

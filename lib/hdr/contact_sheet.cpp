#include "hdr/contact_sheet.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/srgb.hpp"

namespace fest::hdr {

cv::Mat contact_sheet(const std::vector<cv::Mat>& images, int columns, int tile_width) {
  if (images.empty()) throw bad_input("contact sheet: no images");
  if (columns < 1 || tile_width < 1) throw usage_error("contact sheet: columns and tile width must be positive");
  std::vector<cv::Mat> tiles;
  std::vector<float> values;
  for (const cv::Mat& m : images) {
    if (m.depth() != CV_32F || (m.channels() != 1 && m.channels() != 3))
      throw bad_input("contact sheet: expected float grey or RGB radiance");
    cv::Mat rgb = m;
    if (m.channels() == 1) cv::cvtColor(m, rgb, cv::COLOR_GRAY2RGB);
    const int h = std::max(1, int(std::lround(double(rgb.rows) * tile_width / rgb.cols)));
    cv::Mat tile;
    cv::resize(rgb, tile, cv::Size(tile_width, h), 0, 0, cv::INTER_AREA);
    for (int y = 0; y < tile.rows; ++y)
      for (int x = 0; x < tile.cols; ++x) {
        const cv::Vec3f v = tile.at<cv::Vec3f>(y, x);
        const float luminance = 0.2126f * v[0] + 0.7152f * v[1] + 0.0722f * v[2];
        if (luminance > 0 && std::isfinite(luminance)) values.push_back(luminance);
      }
    tiles.push_back(tile);
  }
  double scale = 1;
  if (!values.empty()) {
    const std::size_t k = std::min(values.size() - 1, std::size_t(0.99 * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    if (values[k] > 0) scale = 0.8 / values[k];
  }
  int tile_height = 0;
  for (const cv::Mat& t : tiles) tile_height = std::max(tile_height, t.rows);
  const int cols = std::min<int>(columns, int(tiles.size()));
  const int rows = (int(tiles.size()) + cols - 1) / cols;
  cv::Mat sheet(rows * tile_height, cols * tile_width, CV_8UC3, cv::Scalar::all(0));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int ox = int(i % std::size_t(cols)) * tile_width, oy = int(i / std::size_t(cols)) * tile_height;
    const cv::Mat& t = tiles[i];
    for (int y = 0; y < t.rows; ++y)
      for (int x = 0; x < t.cols; ++x) {
        const cv::Vec3f v = t.at<cv::Vec3f>(y, x);
        cv::Vec3b& out = sheet.at<cv::Vec3b>(oy + y, ox + x);
        for (int c = 0; c < 3; ++c)
          out[c] = std::uint8_t(std::lround(255 * linear_to_srgb(std::isfinite(v[c]) ? v[c] * scale : 0.0)));
      }
  }
  return sheet;
}

}  // namespace fest::hdr

#include "terrainlod/texture_pyramid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fest::terrainlod {

cv::Mat texture_pixels(const cv::Mat& image) {
  if (image.empty()) throw bad_input("texture is empty");
  if (image.depth() != CV_8U && image.depth() != CV_16U)
    throw bad_input("texture must be an 8 or 16-bit image (this one is floating point)");
  cv::Mat m = image;
  if (m.depth() == CV_16U) m.convertTo(m, CV_8U, 1.0 / 257.0);
  if (m.channels() == 2) cv::extractChannel(m, m, 0);
  if (m.channels() == 4) cv::cvtColor(m, m, cv::COLOR_RGBA2RGB);
  return m;
}

ImagePlacement place_image(int iw, int ih, int w, int h) {
  if (iw == w && ih == h) return ImagePlacement::samples;
  // Extent placement: iw / (w - 1) pixels per cell east, ih / (h - 1) north; the two must
  // agree to within one pixel, or the image does not lie on this DEM.
  const double ih_expected = static_cast<double>(iw) * (h - 1) / (w - 1);
  const double iw_expected = static_cast<double>(ih) * (w - 1) / (h - 1);
  if (std::abs(ih_expected - ih) > 1 && std::abs(iw_expected - iw) > 1)
    throw bad_input("texture is {} x {} pixels, which does not fit a DEM of {} x {} samples (an image covering the DEM "
                    "needs its aspect ratio {}:{} in cells, or exactly one pixel per sample)",
                    iw, ih, w, h, w - 1, h - 1);
  return ImagePlacement::extent;
}

cv::Mat leaf_canvas(const cv::Mat& image, ImagePlacement placement, const TextureLayout& lay) {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
    throw bad_input("texture pixels must be 8-bit grey or RGB");
  const int n = lay.canvas(lay.levels);
  const int iw = image.cols, ih = image.rows;
  // Exactly on the texel lattice: the image is the canvas's south-west corner.
  if (placement == ImagePlacement::extent && static_cast<std::int64_t>(iw) * lay.tile == static_cast<std::int64_t>(lay.width - 1) * lay.texels &&
      static_cast<std::int64_t>(ih) * lay.tile == static_cast<std::int64_t>(lay.height - 1) * lay.texels && iw <= n && ih <= n) {
    cv::Mat out;
    cv::copyMakeBorder(image, out, n - ih, 0, 0, n - iw, cv::BORDER_REPLICATE);
    return out;
  }
  return leaf_canvas(image, placement_frame(placement, iw, ih, lay), lay);
}

ImageFrame placement_frame(ImagePlacement placement, int iw, int ih, const TextureLayout& lay) {
  ImageFrame f;
  if (placement == ImagePlacement::extent) {
    f.sx = static_cast<double>(iw) / (lay.width - 1);
    f.sy = static_cast<double>(ih) / (lay.height - 1);
    f.ox = f.oy = -0.5;
  }
  return f;
}

ImageFrame georeferenced_frame(const GridGeoreference& dem, const GridGeoreference& img) {
  ImageFrame f;
  f.sx = dem.dx / img.dx;
  f.ox = (dem.origin_x - img.origin_x) / img.dx;
  f.sy = dem.dy / img.dy;
  // Image row of the DEM's northern row (gy = H - 1), counted from the image's north.
  f.oy = (img.height - 1) - (dem.origin_y + (dem.height - 1) * dem.dy - img.origin_y) / img.dy;
  return f;
}

cv::Mat leaf_canvas(const cv::Mat& image, const ImageFrame& frame, const TextureLayout& lay) {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
    throw bad_input("texture pixels must be 8-bit grey or RGB");
  const int n = lay.canvas(lay.levels);
  const int iw = image.cols, ih = image.rows;
  double sx = frame.sx, sy = frame.sy, ox = frame.ox, oy = frame.oy;
  const double cells_per_texel = static_cast<double>(lay.tile) / lay.texels;
  cv::Mat src = image;
  // More than one pixel per texel: average areas first, then interpolate.
  const double rx = sx * cells_per_texel, ry = sy * cells_per_texel;
  if (rx > 1 || ry > 1) {
    const int w2 = std::max(1, static_cast<int>(std::lround(iw / std::max(rx, 1.0))));
    const int h2 = std::max(1, static_cast<int>(std::lround(ih / std::max(ry, 1.0))));
    cv::resize(image, src, cv::Size(w2, h2), 0, 0, cv::INTER_AREA);
    const double fx = static_cast<double>(w2) / iw, fy = static_cast<double>(h2) / ih;
    // Pixel centres: p' + 0.5 = (p + 0.5) f.
    sx *= fx, ox = (ox + 0.5) * fx - 0.5;
    sy *= fy, oy = (oy + 0.5) * fy - 0.5;
  }
  cv::Mat out(n, n, image.type());
  // In strips, so the coordinate maps stay small for big canvases.
  const int strip = 256;
  for (int r0 = 0; r0 < n; r0 += strip) {
    const int rows = std::min(strip, n - r0);
    cv::Mat mx(rows, n, CV_32FC1), my(rows, n, CV_32FC1);
    for (int r = 0; r < rows; ++r) {
      const double gy = (n - (r0 + r) - 0.5) * cells_per_texel;
      const float py = static_cast<float>((lay.height - 1 - gy) * sy + oy);
      float* px = mx.ptr<float>(r);
      float* pyr = my.ptr<float>(r);
      for (int c = 0; c < n; ++c) {
        px[c] = static_cast<float>((c + 0.5) * cells_per_texel * sx + ox);
        pyr[c] = py;
      }
    }
    cv::Mat dst = out.rowRange(r0, r0 + rows);
    cv::remap(src, dst, mx, my, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  }
  return out;
}

cv::Mat halve_canvas(const cv::Mat& canvas) {
  const int n = canvas.rows / 2, ch = canvas.channels();
  cv::Mat out(n, canvas.cols / 2, canvas.type());
  for (int r = 0; r < n; ++r) {
    const std::uint8_t* a = canvas.ptr<std::uint8_t>(2 * r);
    const std::uint8_t* b = canvas.ptr<std::uint8_t>(2 * r + 1);
    std::uint8_t* o = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < out.cols; ++c)
      for (int k = 0; k < ch; ++k) {
        const int i = 2 * c * ch + k;
        o[c * ch + k] = static_cast<std::uint8_t>((a[i] + a[i + ch] + b[i] + b[i + ch] + 2) / 4);
      }
  }
  return out;
}

cv::Mat tile_texture(const cv::Mat& level_canvas, int level, int x, int y, int texels) {
  const int rows_of_tiles = 1 << level;
  return level_canvas(cv::Rect(x * texels, (rows_of_tiles - 1 - y) * texels, texels, texels)).clone();
}

cv::Mat hillshade_image(const HeightGrid& g, double dx, double dy) {
  auto z = [&](int i, int j) { return g.at(std::clamp(i, 0, g.width - 1), std::clamp(j, 0, g.height - 1)); };
  double lo = g.h[0], hi = lo;
  for (double v : g.h) lo = std::min(lo, v), hi = std::max(hi, v);
  const double alt = 45 * M_PI / 180, az = 315 * M_PI / 180;  // azimuth clockwise from north
  const double sun[3] = {std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
  // Hypsometric tint: low green, olive, brown, high white.
  static const std::array<std::array<double, 4>, 4> stops = {
      {{0.0, 70, 130, 60}, {0.35, 170, 180, 90}, {0.7, 150, 110, 70}, {1.0, 245, 245, 245}}};
  cv::Mat out(g.height, g.width, CV_8UC3);
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i) {
      // Horn's 3 x 3 gradient (edges replicated).
      const double gx = ((z(i + 1, j + 1) + 2 * z(i + 1, j) + z(i + 1, j - 1)) - (z(i - 1, j + 1) + 2 * z(i - 1, j) + z(i - 1, j - 1))) / (8 * dx);
      const double gy = ((z(i - 1, j + 1) + 2 * z(i, j + 1) + z(i + 1, j + 1)) - (z(i - 1, j - 1) + 2 * z(i, j - 1) + z(i + 1, j - 1))) / (8 * dy);
      const double norm = std::sqrt(gx * gx + gy * gy + 1);
      const double shade = std::max(0.0, (-gx * sun[0] - gy * sun[1] + sun[2]) / norm);
      const double t = hi > lo ? (z(i, j) - lo) / (hi - lo) : 0.5;
      std::size_t s = 0;
      while (s + 2 < stops.size() && t > stops[s + 1][0]) ++s;
      const double w = std::clamp((t - stops[s][0]) / (stops[s + 1][0] - stops[s][0]), 0.0, 1.0);
      cv::Vec3b& px = out.at<cv::Vec3b>(g.height - 1 - j, i);
      for (int k = 0; k < 3; ++k) {
        const double tint = stops[s][static_cast<std::size_t>(k) + 1] * (1 - w) + stops[s + 1][static_cast<std::size_t>(k) + 1] * w;
        px[k] = static_cast<std::uint8_t>(std::clamp(std::lround(tint * (0.3 + 0.7 * shade)), 0L, 255L));
      }
    }
  return out;
}

}  // namespace fest::terrainlod

// Images read for composite and --screen-mask, as linear straight RGBA.
#include "image_pixels.hpp"

#include <algorithm>

#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "core/srgb.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"

namespace fest::volrender_tool {

Image load_image(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::image)
    throw bad_input("expected an image, got {} ({})", formats::format_name(in.format), path);
  return formats::read_image(in.bytes, in.format);
}

// Linear, straight (not premultiplied) RGBA of every pixel.
std::vector<float> linear_rgba(const Image& im, const std::string& name) {
  const cv::Mat& m = im.pixels;
  const int ch = m.channels(), depth = m.depth();
  if (depth != CV_8U && depth != CV_16U && depth != CV_32F) throw bad_input("{}: unsupported sample type", name);
  std::vector<float> out(std::size_t(m.rows) * m.cols * 4);
  const double scale = depth == CV_8U ? 1 / 255.0 : depth == CV_16U ? 1 / 65535.0 : 1.0;
  const bool srgb = depth != CV_32F && im.color_space == ColorSpace::srgb;
  for (int j = 0; j < m.rows; ++j)
    for (int i = 0; i < m.cols; ++i) {
      double v[4];
      for (int c = 0; c < ch; ++c)
        v[c] = scale * (depth == CV_8U ? m.ptr<unsigned char>(j)[i * ch + c] : depth == CV_16U ? m.ptr<unsigned short>(j)[i * ch + c]
                                                                                                : m.ptr<float>(j)[i * ch + c]);
      double rgba[4];
      if (ch <= 2) rgba[0] = rgba[1] = rgba[2] = v[0];
      else rgba[0] = v[0], rgba[1] = v[1], rgba[2] = v[2];
      rgba[3] = ch == 2 ? v[1] : ch == 4 ? v[3] : 1.0;
      float* o = &out[(std::size_t(j) * m.cols + i) * 4];
      for (int c = 0; c < 3; ++c) o[c] = static_cast<float>(srgb ? srgb_to_linear(rgba[c]) : rgba[c]);
      o[3] = static_cast<float>(std::clamp(rgba[3], 0.0, 1.0));
    }
  return out;
}

}  // namespace fest::volrender_tool

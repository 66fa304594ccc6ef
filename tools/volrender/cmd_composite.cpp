// volrender composite: images stacked with the "over" operator (docs/volrender.md
// "Composite"), e.g. the four viewers' parts of a Virtual Showcase screen.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/srgb.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"

namespace fest::volrender {
namespace {

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

}  // namespace

int run_composite(const CompositeArgs& a) {
  if (a.inputs.size() < 2) throw usage_error("composite needs at least two images");
  int w = 0, h = 0;
  std::vector<double> C, A;  // premultiplied linear colour and coverage, front to back
  for (std::size_t n = 0; n < a.inputs.size(); ++n) {
    const formats::Input in = formats::load_input(a.inputs[n]);
    if (formats::kind_of(in.format) != formats::Kind::image)
      throw bad_input("expected an image, got {} ({})", formats::format_name(in.format), a.inputs[n]);
    const Image im = formats::read_image(in.bytes, in.format);
    if (n == 0) {
      w = im.pixels.cols, h = im.pixels.rows;
      C.assign(std::size_t(w) * h * 3, 0.0);
      A.assign(std::size_t(w) * h, 0.0);
    } else if (im.pixels.cols != w || im.pixels.rows != h) {
      throw bad_input("{} is {}x{}, the first image {}x{}", a.inputs[n], im.pixels.cols, im.pixels.rows, w, h);
    }
    const auto px = linear_rgba(im, a.inputs[n]);
    for (std::size_t p = 0; p < A.size(); ++p) {
      const double wgt = (1 - A[p]) * px[4 * p + 3];
      for (int c = 0; c < 3; ++c) C[3 * p + c] += wgt * px[4 * p + c];
      A[p] += wgt;
    }
  }
  const bool alpha = std::any_of(A.begin(), A.end(), [](double x) { return x < 1; });
  const int ch = alpha ? 4 : 3;
  Image out;
  out.color_space = ColorSpace::srgb;
  out.pixels.create(h, w, CV_8UC(ch));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t p = std::size_t(j) * w + i;
      auto* q = out.pixels.ptr<unsigned char>(j) + i * ch;
      for (int c = 0; c < 3; ++c) q[c] = static_cast<unsigned char>(std::lround(255.0 * linear_to_srgb(A[p] > 0 ? C[3 * p + c] / A[p] : 0.0)));
      if (alpha) q[3] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(A[p], 0.0, 1.0)));
    }
  write_output(a.output, formats::write_image(out, formats::Format::png));
  return 0;
}

}  // namespace fest::volrender

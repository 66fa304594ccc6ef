// volrender composite: images stacked with the "over" operator (docs/volrender.md
// "Composite"), e.g. the four viewers' parts of a Virtual Showcase screen.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "commands.hpp"
#include "image_pixels.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/srgb.hpp"
#include "formats/image/image_io.hpp"

namespace fest::volrender_tool {

int run_composite(const CompositeArgs& a) {
  if (a.inputs.size() < 2) throw usage_error("composite needs at least two images");
  int w = 0, h = 0;
  std::vector<double> C, A;  // premultiplied linear colour and coverage, front to back
  for (std::size_t n = 0; n < a.inputs.size(); ++n) {
    const Image im = load_image(a.inputs[n]);
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

}  // namespace fest::volrender_tool

// resample display: magnify by an integer factor with a display's point response.
#include "commands.hpp"
#include "core/error.hpp"
#include "image_files.hpp"
#include "sampling/display_model.hpp"
#include "sampling/resize.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

int run_display(const DisplayArgs& a) {
  const DisplayModel& model = a.model;
  const Depth depth = depth_of(a.out.depth);
  LoadedImage in = load_image(a.input);
  const cv::Mat& m = in.image.pixels;
  if (static_cast<long long>(m.cols) * a.factor * m.rows * a.factor > (1LL << 31))
    throw usage_error("display: {}x{} magnified {} times exceeds 2^31 pixels", m.cols, m.rows, a.factor);
  ResizeOptions o;
  o.kernel = model.x;
  o.kernel_y = model.y;
  o.threads = a.threads;
  o.clamp = ClampMode::none;  // the viewer sees the display's overshoot too
  const int image_depth = depth.cv_depth >= 0 ? depth.cv_depth : m.depth();
  const auto f = output_format(a.out.to, a.out.output, image_depth);
  o.output_depth = depth.cv_depth >= 0 ? depth.cv_depth : default_depth(f, m.depth());
  const Image out = resize(in.image, m.cols * a.factor, m.rows * a.factor, o);
  store_image(out, a.out.output, f, depth.half, a.out);
  return 0;
}

}  // namespace fest::resample_tool

// resample mip: a mip-map pyramid, each level made from the previous one, written once all exist.
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "image_files.hpp"
#include "sampling/resize.hpp"
#include "sampling/texture.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

int run_mip(const MipArgs& a) {
  if (a.levels < 0 || a.levels > 40) throw usage_error("--levels {} is out of range", a.levels);
  ResizeOptions o;
  o.kernel = make_kernel(pyramid_kernel(a.filter));
  o.threads = a.threads;
  const LoadedImage in = load_image(a.input);
  const bool is_float = in.image.pixels.depth() == CV_32F;
  const auto f = output_format(a.to, is_float ? "x.exr" : "x.png", in.image.pixels.depth());
  // Every level is made from the previous one (docs/resample.md, "Mip-mapping") and written only
  // once all of them exist: a failure leaves no partial pyramid behind.
  std::vector<Image> levels{in.image};
  while (levels.back().pixels.cols > 1 || levels.back().pixels.rows > 1) {
    if (a.levels > 0 && static_cast<int>(levels.size()) >= a.levels) break;
    const cv::Mat& m = levels.back().pixels;
    levels.push_back(resize(levels.back(), std::max(1, m.cols / 2), std::max(1, m.rows / 2), o));
  }
  for (std::size_t k = 0; k < levels.size(); ++k)
    store_image(levels[k], fmt::format("{}_{}{}", a.prefix, k, formats::format_extension(f)), f, false);
  return 0;
}

}  // namespace fest::resample_tool

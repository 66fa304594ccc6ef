// resample normalmip: the roughness-preserving slope pyramid of a normal or height map.
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "image_files.hpp"
#include "sampling/float_image.hpp"
#include "sampling/slope_pyramid.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

Image float_image(const FloatImage& f) {
  Image img;
  img.color_space = ColorSpace::linear;
  img.pixels = from_working(f, CV_32F, Encoding{});
  return img;
}

}  // namespace

int run_normalmip(const NormalMipArgs& a) {
  if (a.prefix.empty()) throw usage_error("normalmip needs -o PREFIX");
  if (a.normal_map == a.height_map) throw usage_error("normalmip needs exactly one of --normal-map and --height-map");
  const LoadedImage in = load_image(a.input);
  // Integer normal maps store n = 2c − 1 (c = code / max, no sRGB curve); heights are
  // plain values too.
  FloatImage values = to_working(in.image, Encoding{});
  FloatImage slopes;
  if (a.normal_map) {
    if (in.image.pixels.depth() != CV_32F)
      for (auto& v : values.data) v = 2 * v - 1;
    slopes = slopes_from_normals(values);
  } else {
    slopes = with_rewording({{"height scale", "--height-scale"}}, [&] { return slopes_from_height(values, a.height_scale); });
  }
  const auto levels = slope_pyramid(slopes, a.naive, a.threads);
  // Every level is built before the first file is written.
  for (std::size_t k = 0; k < levels.size(); ++k) {
    store_image(float_image(levels[k].normal), fmt::format("{}_{}_normal.exr", a.prefix, k), formats::Format::exr, false);
    store_image(float_image(levels[k].covariance), fmt::format("{}_{}_cov.exr", a.prefix, k), formats::Format::exr, false);
  }
  return 0;
}

}  // namespace fest::resample_tool

// resample render: analytic scenes, supersampled with a sample pattern and pixel filter.
#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "image_files.hpp"
#include "sampling/render.hpp"
#include "sampling/resize.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

int run_render(const RenderArgs& a) {
  const int w = a.width, h = a.height;
  const auto& params = a.params;
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.samples = a.ground_truth ? a.gt_spp : a.spp;
  o.pattern = a.ground_truth ? Pattern::jitter : a.pattern;
  o.seed = a.seed;
  o.threads = a.threads;
  if (a.scene != "point") {
    o.pixel_filter = a.pixel_filter;
    o.filter_scale = a.filter_scale;
  }
  check_sample_count(o.pattern, o.samples);
  const Depth depth = depth_of(a.out.depth.value_or(OutputDepth::f32));
  const auto f = output_format(a.out.to, a.out.output, depth.cv_depth);

  const Scene scene = make_scene(a.scene, params, w, h, a.point_filter);
  const FloatImage img = render(scene, o);
  Image out;
  out.color_space = ColorSpace::linear;
  Encoding enc;
  // Integer outputs are sRGB codes of the linear scene values, or the plain values
  // (--colorspace linear: what other tools filter without decoding).
  enc.decode_srgb = depth.cv_depth != CV_32F && a.colorspace == RenderColor::srgb;
  out.pixels = from_working(img, depth.cv_depth, enc);
  if (enc.decode_srgb) out.color_space = ColorSpace::srgb;
  store_image(out, a.out.output, f, depth.half, a.out);
  return 0;
}

}  // namespace fest::resample_tool

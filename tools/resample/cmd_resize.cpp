// resample resize: an image through the separable resize of lib/sampling.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "image_files.hpp"
#include "sampling/resize.hpp"
#include "sizes.hpp"
#include "streamed_input.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

// The target size from --size / --width / --height / --scale, derived in double and
// checked (sizes.hpp) before anything is allocated.
std::pair<int, int> target_size(const ResizeArgs& a, int w_in, int h_in) {
  const int given = a.size.has_value() + (a.width > 0 || a.height > 0) + (!a.scale.empty());
  if (given != 1) throw usage_error("give exactly one of --size, --width/--height, --scale");
  if (a.size) return *a.size;
  if (!a.scale.empty()) {
    if (a.scale.size() > 2) throw usage_error("--scale takes S or Sx,Sy");
    const double sx = a.scale[0], sy = a.scale.size() == 2 ? a.scale[1] : a.scale[0];
    if (!(sx > 0 && sy > 0) || !std::isfinite(sx) || !std::isfinite(sy))
      throw usage_error("--scale {},{} must be positive", sx, sy);
    return checked_size(w_in * sx, h_in * sy, "--scale");
  }
  if (a.width < 0 || a.height < 0) throw usage_error("--width/--height must be positive");
  if (a.width > 0 && a.height > 0) return checked_size(a.width, a.height, "--width/--height");
  // The side left out keeps the aspect ratio, rounded (halves away from zero) and at
  // least 1: --width 1 of a 101x37 image is 1x1, not an error about a side of 0.37.
  const auto kept = [](double side) { return std::max(1.0, std::round(side)); };
  if (a.width > 0) return checked_size(a.width, kept(static_cast<double>(h_in) * a.width / w_in), "--width");
  return checked_size(kept(static_cast<double>(w_in) * a.height / h_in), a.height, "--height");
}

}  // namespace

int run_resize(const ResizeArgs& a) {
  ResizeOptions o;
  o.kernel = a.filter;
  o.edge = a.edge;
  o.clamp = a.clamp;
  o.premultiply_alpha = a.alpha == AlphaMode::premul;
  o.linear_light = a.colorspace != ResizeColor::codes;
  o.hicomp = a.hicomp;
  o.dither = a.dither;
  o.seed = a.seed;
  o.threads = a.threads;
  if (!a.shift.empty()) {
    if (a.shift.size() != 2) throw usage_error("--shift takes dx,dy");
    o.shift_x = a.shift[0];
    o.shift_y = a.shift[1];
  }
  const Depth depth = depth_of(a.out.depth);

  auto pick_colour = [&](ColorSpace stored) {
    if (a.colorspace == ResizeColor::srgb) return ColorSpace::srgb;
    if (a.colorspace == ResizeColor::linear) return ColorSpace::linear;
    return stored;
  };
  auto finish = [&](int in_w, int in_h, int in_depth, auto&& run) {
    const auto [w, h] = target_size(a, in_w, in_h);
    const auto f = output_format(a.out.to, a.out.output, depth.cv_depth >= 0 ? depth.cv_depth : in_depth);
    o.output_depth = depth.cv_depth >= 0 ? depth.cv_depth : default_depth(f, in_depth);
    // lib/sampling names the sinc kernel's limits in its terms; these are the flags that set them.
    const Image out = with_rewording(
        {{"does not take a sub-pixel shift", "does not take --shift"}, {"(edge mode clamp or reflect)", "(--edge clamp or reflect)"}},
        [&] { return run(w, h); });
    store_image(out, a.out.output, f, depth.half, a.out);
    return 0;
  };
  // Raw Netpbm and PFM files stream through the passes a band of rows at a time.
  if (const auto streamed = StreamedInput::open(a.input))
    return finish(streamed->width(), streamed->height(), CV_MAT_DEPTH(streamed->type()),
                  [&](int w, int h) { return resize(*streamed, pick_colour(streamed->color_space()), w, h, o); });
  LoadedImage in = load_image(a.input);
  in.image.color_space = pick_colour(in.image.color_space);
  const cv::Mat& m = in.image.pixels;
  return finish(m.cols, m.rows, m.depth(), [&](int w, int h) { return resize(in.image, w, h, o); });
}

}  // namespace fest::resample_tool

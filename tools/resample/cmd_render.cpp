// resample render: analytic scenes, supersampled with a sample pattern and pixel filter.
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "image_files.hpp"
#include "sampling/kernel_params.hpp"
#include "sampling/render.hpp"
#include "sampling/resize.hpp"
#include "sizes.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

// NAME[:params][,radius=R] -> the kernel and the stretch that gives it radius R.
std::pair<Kernel, double> pixel_filter(const std::string& spec) {
  std::string rest = spec;
  double radius = 0;
  const auto pos = rest.find("radius=");
  if (pos != std::string::npos && pos > 0 && (rest[pos - 1] == ':' || rest[pos - 1] == ',')) {
    const auto end = rest.find(',', pos);
    const std::string value = rest.substr(pos + 7, end == std::string::npos ? std::string::npos : end - pos - 7);
    char* stop = nullptr;
    radius = std::strtod(value.c_str(), &stop);
    if (value.empty() || *stop != '\0' || !(radius > 0 && radius <= 64))
      throw usage_error("--pixel-filter: radius '{}' must be a number in (0, 64]", value);
    rest.erase(pos - 1, (end == std::string::npos ? rest.size() : end) - pos + 1);
  }
  const Kernel k = make_kernel(rest);
  if (!k.reconstruction.empty()) throw usage_error("--pixel-filter cannot be a dual prefilter");
  const double scale = radius > 0 && k.radius > 0 && std::isfinite(k.radius) ? radius / k.radius : 1.0;
  return {k, scale};
}

}  // namespace

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
  // The point scene takes the radial lowpass/bandpass filters the others do not.
  const bool radial = a.pixel_filter.rfind("lowpass", 0) == 0 || a.pixel_filter.rfind("bandpass", 0) == 0;
  if (radial && a.scene != "point") throw usage_error("--pixel-filter {} is for --scene point only", a.pixel_filter);
  std::map<std::string, double> scene_params = params;
  std::string point_filter = "lowpass";
  if (a.scene == "point") {
    const KernelSpelling s = split_kernel_spelling(a.pixel_filter);
    if (s.name == "bandpass") {
      for (const auto& [k, v] : parse_kernel_params("bandpass", s.rest, {{"lo", 0.2}})) scene_params[k] = v;
      point_filter = "bandpass";
    } else if (s.name == "lowpass") {
      if (!s.rest.empty()) throw usage_error("--pixel-filter lowpass takes no parameters");
    } else {
      point_filter = a.pixel_filter;
    }
  } else {
    const auto [k, scale] = pixel_filter(a.pixel_filter);
    o.pixel_filter = k;
    o.filter_scale = scale;
  }
  check_sample_count(o.pattern, o.samples);
  const Depth depth = depth_of(a.out.depth.value_or(OutputDepth::f32));
  const auto f = output_format(a.out.to, a.out.output, depth.cv_depth);

  const Scene scene = make_scene(a.scene, scene_params, w, h, point_filter);
  const FloatImage img = render(scene, o);
  Image out;
  out.color_space = ColorSpace::linear;
  Encoding enc;
  // Integer outputs are sRGB codes of the linear scene values, or the plain values
  // (--colorspace linear: what other tools filter without decoding).
  enc.decode_srgb = depth.cv_depth != CV_32F && a.colorspace == RenderColor::srgb;
  out.pixels = from_working(img, depth.cv_depth, enc);
  if (enc.decode_srgb) out.color_space = ColorSpace::srgb;
  store_image(out, a.out.output, f, depth.half);
  return 0;
}

}  // namespace fest::resample_tool

// resample texture: a texture seen through a screen mapping, filtered by mip-map lookups
// (or the dense ground truth), as an image; optionally the mask of anisotropic pixels.
#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "image_files.hpp"
#include "sampling/float_image.hpp"
#include "sampling/texture.hpp"
#include "sizes.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

// One channel in linear light: grey as is, colour as the mean of R, G, B.
FloatImage grey_linear(const Image& img) {
  Encoding enc;
  enc.decode_srgb = img.color_space == ColorSpace::srgb && img.pixels.depth() != CV_32F;
  const FloatImage f = to_working(img, enc);
  if (f.channels <= 2) {
    FloatImage g(f.width, f.height, 1);
    for (std::size_t i = 0; i < g.data.size(); ++i) g.data[i] = f.data[i * static_cast<std::size_t>(f.channels)];
    return g;
  }
  FloatImage g(f.width, f.height, 1);
  for (std::size_t i = 0; i < g.data.size(); ++i) {
    const float* p = f.data.data() + i * static_cast<std::size_t>(f.channels);
    g.data[i] = (p[0] + p[1] + p[2]) / 3;
  }
  return g;
}

}  // namespace

int run_texture(const TextureArgs& a) {
  const int w = a.width, h = a.height;
  TextureOptions o = a.method;
  o.lod_bias = a.lod_bias;
  o.threads = a.threads;
  if (!std::isfinite(a.lod_bias)) throw usage_error("--lod-bias must be finite");
  const Depth depth = depth_of(a.out.depth);

  const LoadedImage tex = load_image(a.tex);
  const FloatImage texture = grey_linear(tex.image);
  FloatImage uv;
  if (!a.uv.empty()) {
    const LoadedImage u = load_image(a.uv);
    if (u.image.pixels.channels() != 2)
      throw bad_input("--uv needs an image with 2 channels (u, v), got {} ({})", u.image.pixels.channels(), a.uv);
    uv = to_working(u.image, Encoding{});
    if (uv.width != w || uv.height != h) throw bad_input("--uv is {}x{}, --size {}x{}", uv.width, uv.height, w, h);
  }
  const TextureMap map = with_rewording({{"plane view:", "--map plane:"}, {"texture coordinates need", "--uv needs"}}, [&] {
    return a.map ? plane_map(a.map->h, a.map->pitch, a.map->fov, a.map->period, w, h, texture.width, texture.height)
                 : table_map(uv, texture.width, texture.height);
  });
  FloatImage screen;
  if (a.aniso_mask > 0) {
    const FloatImage aniso = footprint_anisotropy(map, w, h);
    screen = FloatImage(w, h, 1);
    for (std::size_t i = 0; i < aniso.data.size(); ++i) screen.data[i] = aniso.data[i] > a.aniso_mask ? 1.0f : 0.0f;
  } else if (a.ground_truth) {
    screen = texture_ground_truth(texture, map, w, h, a.seed, a.threads);
  } else {
    screen = texture_screen(build_pyramid(texture, a.mip, a.threads), map, w, h, o);
  }
  const int out_depth = a.aniso_mask > 0 ? CV_8U : depth.cv_depth >= 0 ? depth.cv_depth : CV_32F;
  const auto f = output_format(a.out.to, a.out.output, out_depth);
  Image out;
  Encoding enc;
  enc.decode_srgb = out_depth != CV_32F && a.aniso_mask <= 0;  // integer images hold sRGB codes
  out.pixels = from_working(screen, out_depth, enc);
  out.color_space = enc.decode_srgb ? ColorSpace::srgb : ColorSpace::linear;
  store_image(out, a.out.output, f, depth.half, a.out);
  return 0;
}

}  // namespace fest::resample_tool

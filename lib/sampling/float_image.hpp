#pragma once
// The working form of resize (docs/resample.md): 32-bit float, interleaved, C channels, rows
// top-down, in linear light with premultiplied alpha unless told otherwise.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace fest::sampling {

struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> data;  // width * height * channels values

  FloatImage() = default;
  FloatImage(int w, int h, int c)
      : width(w), height(h), channels(c),
        data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(c), 0.0f) {}
  float* row(int y) { return data.data() + static_cast<std::size_t>(y) * width * channels; }
  const float* row(int y) const { return data.data() + static_cast<std::size_t>(y) * width * channels; }
};

// How stored values relate to the working values.
struct Encoding {
  bool decode_srgb = false;  // colour channels are sRGB codes: decode to linear and back
  bool premultiply = false;  // an alpha channel exists and colour is multiplied by it
  bool dither = false;       // from_working: triangular noise of ±½ LSB before rounding
  std::uint64_t seed = 1;    // of the dither noise (a pure function of seed and position)
};

// The channel that holds alpha (grey+alpha or RGBA), or -1.
int alpha_channel(int channels);

// Checks depth (8U/16U/32F) and channel count (1-4): bad_input otherwise.
void check_supported(const Image& in);

// Integer codes are scaled to [0, 1]; sRGB-decoded and premultiplied as `enc` says.
FloatImage to_working(const Image& in, const Encoding& enc);

// One row of to_working into dst (width × channels floats): lets a first resize pass
// stream over the stored pixels instead of holding a float copy of the whole input.
void decode_row(const cv::Mat& m, int y, const Encoding& enc, float* dst);

// The inverse of to_working, into an image of the given depth: un-premultiply (α < 1e-6
// gives colour 0), sRGB-encode, and round to nearest (saturating) for integer depths,
// dithered when `enc.dither`.
cv::Mat from_working(const FloatImage& img, int depth, const Encoding& enc);

}  // namespace fest::sampling

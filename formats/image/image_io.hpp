#pragma once
// Images: PNG, PGM/PPM/PAM (8/16-bit), PFM, EXR, TIFF; JPEG (8-bit grey or RGB, baseline,
// EXIF orientation not applied: the pixels come back in stored order).

#include <array>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "core/image.hpp"
#include "core/progress_fn.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

struct ImageHeader {
  int width = 0;
  int height = 0;
  int channels = 0;
  int bits = 0;          // 8, 16 or 32 (float)
  bool is_float = false;
};

// The JPEG quality every tool writes unless told otherwise (--quality): 95, where
// libjpeg's quantisation tables are scaled to 10 % of the standard ones (Annex K) -- a
// smooth image comes back within a few levels. cjpeg defaults to 75, ImageMagick to 92.
inline constexpr int default_jpeg_quality = 95;

struct ImageWriteOptions {
  bool ascii = false;      // PGM/PPM: plain (P2/P3) instead of raw (P5/P6)
  bool exr_half = false;   // EXR: 16-bit half channels instead of 32-bit float
  int png_compression = 6; // PNG: zlib level 0-9 (1: several times faster, e.g. capture's raw shots)
  bool png_huffman_only = false;  // PNG: unfiltered rows, zlib Huffman coding only (noisy raw data: faster and smaller)
  int jpeg_quality = default_jpeg_quality;  // JPEG: 1 (smallest) to 100; 0 refuses JPEG (a caller that must not be lossy)
  // PGM/PPM/JPEG of an image with alpha: composite it over `background` (display values
  // 0-1, R G B; grey images take its luminance) in linear light instead of refusing it.
  bool flatten = false;
  std::array<double, 3> background{1, 1, 1};
  // PNG and EXR: called with (rows encoded, rows) as zlib works through the image --
  // a 55-megapixel PNG takes about 10 s to deflate, a float EXR about 14 s.
  ProgressFn progress;
};

// Reads only the header (dimensions, channels, depth) and checks it is plausible:
// cheap, and the first line of defence against absurd sizes.
ImageHeader read_image_header(std::string_view bytes, Format format);

// Throws fest::Error(Status::bad_input) for malformed input. Pixels come back in RGB(A)
// order (core/image.hpp).
Image read_image(std::string_view bytes, Format format);

// Throws Status::bad_input when the format cannot hold the image (a float image as PNG,
// 4 channels as PGM, 16-bit as JPEG) -- convert explicitly instead of silently losing data.
// An alpha channel that is opaque at every pixel holds nothing and is dropped for the
// formats without alpha (PGM, PPM, JPEG); any other alpha is refused, with the count of
// pixels that are not opaque, unless ImageWriteOptions::flatten asks for compositing.
std::string write_image(const Image& image, Format format, const ImageWriteOptions& options = {});

// write_image with an "encoding PNG" (or EXR) bar on standard error (core/progress.hpp)
// for a PNG or EXR of 4 megapixels or more, when `bar_wanted` (progress_wanted of the
// tool's --progress): deflating takes about 2 s per 10 megapixels (PNG) and 2.6 s (float
// EXR); other formats are fast.
std::string write_image_with_bar(const Image& image, Format format, ImageWriteOptions options, bool bar_wanted);

nlohmann::json describe_image(const Image& image);

}  // namespace fest::formats

// Dispatch of the image API (image_io.hpp) to the per-format header parsers and codecs.
// Every read parses and checks the header first, so no decoder sees an absurd one.
#include "formats/image/image_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <zlib.h>

#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/srgb.hpp"
#include "formats/image/codec_plugins.hpp"
#include "formats/image/image_codecs.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats {
namespace {

using namespace image_detail;

bool is_netpbm(Format f) { return f == Format::pgm || f == Format::ppm || f == Format::pam; }

const char* depth_label(int depth) {
  switch (depth) {
    case CV_8U: return "8-bit";
    case CV_16U: return "16-bit";
    case CV_32F: return "float";
    default: return "unsupported";
  }
}

[[noreturn]] void refuse(const cv::Mat& m, Format f, const char* why) {
  throw bad_input("cannot write a {}-channel {} image as {}: {}", m.channels(), depth_label(m.depth()),
                  format_name_of(f), why);
}

// The largest sample value of an opaque pixel at this depth.
double opaque_value(int depth) { return depth == CV_8U ? 255.0 : depth == CV_16U ? 65535.0 : 1.0; }

// Straight (not premultiplied) colour C with alpha a over the background B, in linear
// light for sRGB-encoded data: C' = a C + (1 - a) B, then encoded and rounded. Integer
// samples only (the callers refuse float first).
template <typename T>
cv::Mat composite_over(const cv::Mat& m, bool srgb, const std::array<double, 3>& background) {
  const int colours = m.channels() - 1;
  const double top = opaque_value(m.depth());
  const auto to_linear = [srgb](double v) { return srgb ? srgb_to_linear(v) : std::clamp(v, 0.0, 1.0); };
  const auto to_stored = [srgb](double v) { return srgb ? linear_to_srgb(v) : std::clamp(v, 0.0, 1.0); };
  double bg[3] = {to_linear(background[0]), to_linear(background[1]), to_linear(background[2])};
  if (colours == 1) bg[0] = 0.2126 * bg[0] + 0.7152 * bg[1] + 0.0722 * bg[2];  // Rec. 709 luminance
  cv::Mat out(m.rows, m.cols, CV_MAKETYPE(m.depth(), colours));
  for (int y = 0; y < m.rows; ++y) {
    const T* in = m.ptr<T>(y);
    T* o = out.ptr<T>(y);
    for (int x = 0; x < m.cols; ++x, in += colours + 1, o += colours) {
      const double a = in[colours] / top;
      for (int c = 0; c < colours; ++c)
        o[c] = T(std::lround(to_stored(a * to_linear(in[c] / top) + (1 - a) * bg[c]) * top));
    }
  }
  return out;
}

// For a format without alpha: an alpha channel (the last of 2 or 4) that is opaque at every
// pixel carries nothing and is dropped; otherwise the image is composited over the
// background when the caller asked (flatten), else refused with the count of pixels it
// would change (nothing is lost silently).
cv::Mat without_opaque_alpha(const Image& image, Format f, const ImageWriteOptions& options) {
  const cv::Mat& m = image.pixels;
  const int channels = m.channels();
  if (channels != 2 && channels != 4) return m;
  cv::Mat alpha;
  cv::extractChannel(m, alpha, channels - 1);
  const double opaque = opaque_value(m.depth());
  const std::size_t see_through = m.total() - std::size_t(cv::countNonZero(alpha >= opaque));
  if (see_through > 0 && options.flatten) {
    const bool srgb = image.color_space == ColorSpace::srgb;
    return m.depth() == CV_8U ? composite_over<std::uint8_t>(m, srgb, options.background)
                              : composite_over<std::uint16_t>(m, srgb, options.background);
  }
  if (see_through > 0)
    throw bad_input("cannot write a {}-channel {} image as {}: it has an alpha channel, which {} cannot hold, and {} of "
                    "{} pixels are not opaque; flatten it (--flatten, --background) or write PNG or TIFF",
                    channels, depth_label(m.depth()), format_name_of(f), format_name_of(f), see_through, m.total());
  cv::Mat colour(m.rows, m.cols, CV_MAKETYPE(m.depth(), channels - 1));
  static constexpr int from_to[] = {0, 0, 1, 1, 2, 2};
  cv::mixChannels(&m, 1, &colour, 1, from_to, std::size_t(channels - 1));
  return colour;
}

}  // namespace

namespace image_detail {
const char* format_name_of(Format f) {
  switch (f) {
    case Format::png: return "PNG";
    case Format::pgm: return "PGM";
    case Format::ppm: return "PPM";
    case Format::pam: return "PAM";
    case Format::pfm: return "PFM";
    case Format::exr: return "EXR";
    case Format::tiff: return "TIFF";
    case Format::jpeg: return "JPEG";
    default: return "a non-image format";
  }
}
}  // namespace image_detail

ImageHeader read_image_header(std::string_view bytes, Format format) {
  if (bytes.empty()) throw bad_input("{} header: the input is empty", format_name_of(format));
  switch (format) {
    case Format::png: return read_png_header(bytes);
    case Format::tiff: return read_tiff_header(bytes);
    case Format::exr: return read_exr_header(bytes);
    case Format::jpeg: return read_jpeg_header(bytes);
    case Format::pfm: return read_netpbm_layout(bytes, true).header;
    case Format::pgm: case Format::ppm: case Format::pam: return read_netpbm_layout(bytes, false).header;
    default: throw bad_input("{} is not an image format", format_name_of(format));
  }
}

Image read_image(std::string_view bytes, Format format) {
  Image image;
  if (is_netpbm(format)) {
    if (bytes.empty()) throw bad_input("{} header: the input is empty", format_name_of(format));
    image.pixels = decode_netpbm(bytes, read_netpbm_layout(bytes, false));
    return image;
  }
  if (format == Format::pfm) {
    if (bytes.empty()) throw bad_input("PFM header: the input is empty");
    image.pixels = decode_pfm(bytes, read_netpbm_layout(bytes, true));
    image.color_space = ColorSpace::linear;
    return image;
  }
  if (format == Format::exr) {
    if (bytes.empty()) throw bad_input("EXR header: the input is empty");
    image.pixels = exr_codec().decode(bytes);
    image.color_space = ColorSpace::linear;
    return image;
  }
  const ImageHeader header = read_image_header(bytes, format);
  const char* what = format_name_of(format);
  switch (format) {
    case Format::png: image.pixels = decode_png(bytes); break;
    case Format::jpeg: image.pixels = decode_jpeg(bytes); break;
    case Format::tiff: image.pixels = tiff_codec().decode(bytes, header); break;
    default: throw bad_input("{} is not an image format", what);
  }
  const cv::Mat& decoded = image.pixels;
  if (decoded.cols != header.width || decoded.rows != header.height)
    throw bad_input("{} data: decoded {} x {} pixels, header says {} x {}", what, decoded.cols, decoded.rows,
                    header.width, header.height);
  const int expected_depth = header.is_float ? CV_32F : (header.bits == 16 ? CV_16U : CV_8U);
  if (decoded.depth() != expected_depth)
    throw bad_input("{} data: decoded {} samples, header says {}", what, depth_label(decoded.depth()),
                    depth_label(expected_depth));
  // Float TIFF holds scene-referred values.
  if (header.is_float) image.color_space = ColorSpace::linear;
  return image;
}

std::string write_image(const Image& image, Format format, const ImageWriteOptions& options) {
  const cv::Mat& m = image.pixels;
  if (m.empty() || m.dims != 2) throw bad_input("cannot write an empty image");
  const int depth = m.depth(), channels = m.channels();
  if (depth != CV_8U && depth != CV_16U && depth != CV_32F)
    refuse(m, format, "fest images are 8-bit, 16-bit or float");
  const bool integer = depth != CV_32F;
  switch (format) {
    case Format::png:
      if (!integer) refuse(m, format, "PNG holds 8 or 16-bit integers; convert explicitly");
      if (channels == 2) return encode_png_grey_alpha(m);
      if (options.png_huffman_only && options.png_compression > 0)
        return encode_png_unfiltered(m, std::min(options.png_compression, 9), Z_HUFFMAN_ONLY);
      return encode_png(m, std::clamp(options.png_compression, 0, 9),
                        options.png_huffman_only ? Z_HUFFMAN_ONLY : Z_DEFAULT_STRATEGY, options.progress);
    case Format::pgm:
    case Format::ppm: {
      const int wanted = format == Format::pgm ? 1 : 3;
      if (!integer) refuse(m, format, "PGM/PPM hold 8 or 16-bit integers; use PFM for float");
      const cv::Mat colour = without_opaque_alpha(image, format, options);
      if (colour.channels() != wanted) refuse(m, format, format == Format::pgm ? "PGM holds one channel" : "PPM holds RGB");
      return encode_pnm(colour, options.ascii);
    }
    case Format::pam:
      if (!integer) refuse(m, format, "PAM holds 8 or 16-bit integers; use PFM or EXR for float");
      return encode_pam(m);
    case Format::pfm:
      if (integer) refuse(m, format, "PFM holds float; convert explicitly");
      if (channels != 1 && channels != 3) refuse(m, format, "PFM holds grey or RGB");
      return encode_pfm(m);
    case Format::exr:
      if (integer) refuse(m, format, "EXR is written as half or float; convert explicitly");
      return exr_codec().encode(m, options.exr_half, options.progress);
    case Format::tiff:
      if (channels == 2) refuse(m, format, "fest's TIFF writer takes 1, 3 or 4 channels");
      return tiff_codec().encode(m);
    case Format::jpeg: {
      // Lossy compression has no place in a measurement pipeline (docs/capture.md §3): a
      // caller that must not be lossy sets jpeg_quality 0 (capture refuses JPEG itself).
      if (options.jpeg_quality <= 0) refuse(m, format, "this output must not be lossy; use PNG or TIFF");
      if (depth != CV_8U)
        refuse(m, format, "JPEG holds 8-bit samples; convert explicitly (resample's --depth 8) or write PNG or TIFF");
      return encode_jpeg(without_opaque_alpha(image, format, options), std::clamp(options.jpeg_quality, 1, 100));
    }
    default:
      throw bad_input("cannot write an image as {}", format_name_of(format));
  }
}

std::string write_image_with_bar(const Image& image, Format format, ImageWriteOptions options, bool bar_wanted) {
  // An 8000 x 6927 upscale of a photo (55 megapixels) spends about 10 s of its 11.8 s in
  // zlib as PNG (level 6, libpng's adaptive filters) and about 14 s as float EXR (ZIP);
  // below 4 megapixels writing ends before a bar would be read, and the other formats are
  // written at memory speed (PPM 1.3 s, PFM 3.1 s for the whole resize).
  constexpr double kBarFromPixels = 4e6;
  const cv::Mat& m = image.pixels;
  const bool slow = format == Format::png || format == Format::exr;
  if (!slow || double(m.rows) * double(m.cols) < kBarFromPixels) return write_image(image, format, options);
  Progress bar(format == Format::png ? "encoding PNG" : "encoding EXR", std::uint64_t(m.rows), bar_wanted);
  options.progress = bar.callback();
  std::string bytes = write_image(image, format, options);
  bar.finish();
  return bytes;
}

}  // namespace fest::formats

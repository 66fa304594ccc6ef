#include "image_files.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::formats;

LoadedImage load_image(const std::string& path) {
  const Input in = load_input(path);
  if (kind_of(in.format) != Kind::image)
    throw bad_input("'{}' is {} data ({}), not an image", in.name, kind_name(kind_of(in.format)), format_name(in.format));
  LoadedImage out{parse(in, read_image), in.format};
  if (out.image.pixels.empty() || out.image.pixels.rows == 0 || out.image.pixels.cols == 0)
    throw bad_input("the image is empty ({})", in.name);
  return out;
}

Depth depth_of(std::optional<OutputDepth> depth) {
  if (!depth) return {};
  switch (*depth) {
    case OutputDepth::u8: return {CV_8U, false};
    case OutputDepth::u16: return {CV_16U, false};
    case OutputDepth::f16: return {CV_32F, true};
    case OutputDepth::f32: break;
  }
  return {CV_32F, false};
}

Format output_format(const std::optional<OutputFormat>& to, const std::string& path, int cv_depth) {
  OutputFormat f{cv_depth == CV_32F ? Format::pfm : Format::png, false};
  if (to)
    f = *to;
  else if (!is_stdio(path))
    f = output_format_from_path(path);
  if (kind_of(f.format) != Kind::image) throw usage_error("'{}' is not an image format", format_name(f.format));
  if (f.gzip) throw usage_error("compressed image output is not offered (got {}.gz)", format_name(f.format));
  return f.format;
}

int default_depth(Format f, int image_depth) {
  const bool float_format = f == Format::pfm || f == Format::exr;
  if (float_format) return CV_32F;
  if (f == Format::tiff) return image_depth;  // TIFF holds 8, 16 bits and float alike
  if (f == Format::jpeg) return CV_8U;        // baseline JPEG holds 8 bits only
  if (image_depth == CV_32F) return CV_8U;
  return image_depth;
}

void store_image(const Image& image, const std::string& path, Format f, bool half, const ImageOutput& out) {
  if (half && f != Format::exr) throw usage_error("--depth f16 needs EXR output (--to exr)");
  const int d = image.pixels.depth();
  if (f == Format::jpeg && d != CV_8U)
    throw usage_error("JPEG holds 8-bit samples: use --depth 8 (or leave --depth out), or PNG or TIFF for {}",
                      d == CV_16U ? "16 bits" : "float");
  if (d == CV_32F && (f == Format::png || f == Format::pgm || f == Format::ppm || f == Format::pam))
    throw usage_error("{} cannot hold float samples: use --depth 8 or 16, or a float format (pfm, exr, tiff)",
                      format_name(f));
  if (d != CV_32F && (f == Format::pfm || f == Format::exr))
    throw usage_error("{} holds float samples: use --depth f32 (or leave --depth out)", format_name(f));
  ImageWriteOptions w;
  w.exr_half = half;
  w.jpeg_quality = out.quality;
  w.flatten = out.flatten;
  w.background = out.background;
  // Encoded completely before anything is written: no partial output on failure.
  const std::string bytes = write_image_with_bar(image, f, w, progress_wanted(out.progress));
  store_output(path, bytes, false);
}

}  // namespace fest::resample_tool

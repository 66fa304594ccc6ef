// PNG through libpng directly (not OpenCV's imgcodecs, whose dependencies -- GDAL, gdcm,
// poppler, ffmpeg -- mapped ~140 shared libraries into every tool at start-up, paid once
// per file when tools run from Makefiles over thousands of files). The transforms are
// the ones OpenCV 4.6 applied for IMREAD_UNCHANGED, so pixels are unchanged:
// palette -> RGB (RGBA with tRNS), RGB + tRNS -> RGBA, grey 1/2/4-bit -> 8-bit (scaled),
// grey + alpha kept as two channels, 16-bit samples in native byte order. Encoding uses
// the zlib level and strategy OpenCV was given, with libpng's default adaptive filters,
// so the bytes written are the same as before.
//
// libpng reports errors through a callback that must not return: it records the message
// and longjmps back to the setjmp in this file, which turns it into fest::Error. Only
// plain C data lives in the frames a longjmp crosses. Warnings (an sRGB profile libpng
// dislikes, an ancillary chunk with a bad CRC) do not affect pixels and are dropped
// rather than printed.
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <png.h>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {
namespace {

struct PngState {
  std::string_view in;  // reading
  std::size_t at = 0;
  std::string* out = nullptr;  // writing
  const ProgressFn* progress = nullptr;  // writing: told after each row
  png_uint_32 rows = 0;
  char message[256] = {};
};

void on_error(png_structp png, png_const_charp message) {
  auto* s = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(s->message, sizeof s->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* s = static_cast<PngState*>(png_get_io_ptr(png));
  if (s->in.size() - s->at < n) png_error(png, "truncated: the file ends inside the image data");
  std::memcpy(out, s->in.data() + s->at, n);
  s->at += n;
}

void write_bytes(png_structp png, png_bytep data, png_size_t n) {
  static_cast<PngState*>(png_get_io_ptr(png))->out->append(reinterpret_cast<const char*>(data), n);
}

void flush_nothing(png_structp) {}

// libpng calls this after each row it has filtered and handed to zlib. Reported every 64
// rows: the callback draws a bar, which redraws at most ten times a second anyway.
void row_written(png_structp png, png_uint_32 row, int /*pass*/) {
  const auto* s = static_cast<const PngState*>(png_get_io_ptr(png));
  if (row % 64 == 0 || row == s->rows) (*s->progress)(row, s->rows);
}

bool little_endian() {
  const std::uint16_t one = 1;
  return *reinterpret_cast<const std::uint8_t*>(&one) == 1;
}

// The libpng calls between setjmp and a possible longjmp. `pixels` and `rows` belong to
// the caller, so nothing with a destructor lives in this frame.
bool read_png(png_structp png, png_infop info, cv::Mat& pixels, std::vector<png_bytep>& rows, PngState& state) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &state, read_bytes);
  png_read_info(png, info);
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0;
  png_get_IHDR(png, info, &width, &height, &bit_depth, &color_type, nullptr, nullptr, nullptr);
  const bool trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  int channels = 1;
  switch (color_type) {
    case PNG_COLOR_TYPE_RGB:
    case PNG_COLOR_TYPE_PALETTE: channels = trns ? 4 : 3; break;
    case PNG_COLOR_TYPE_GRAY_ALPHA: channels = 2; break;
    case PNG_COLOR_TYPE_RGB_ALPHA: channels = 4; break;
    default: channels = 1;  // grey; a grey tRNS key is not turned into alpha (as OpenCV did)
  }
  if (bit_depth == 16 && little_endian()) png_set_swap(png);
  if (channels == 4) png_set_tRNS_to_alpha(png);
  else if (channels != 2) png_set_strip_alpha(png);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if ((color_type & PNG_COLOR_MASK_COLOR) == 0 && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);

  pixels.create(int(height), int(width), CV_MAKETYPE(bit_depth == 16 ? CV_16U : CV_8U, channels));
  if (png_get_rowbytes(png, info) != pixels.cols * pixels.elemSize())
    png_error(png, "unexpected row size after the colour transforms");
  rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels.ptr<png_byte>(int(y));
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  return true;
}

bool write_png(png_structp png, png_infop info, const cv::Mat& pixels, std::vector<png_bytep>& rows, int level,
               int strategy, PngState& state) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, &state, write_bytes, flush_nothing);
  if (state.progress && *state.progress) png_set_write_status_fn(png, row_written);
  png_set_compression_level(png, level);
  png_set_compression_strategy(png, strategy);
  static constexpr int colour_type[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                         PNG_COLOR_TYPE_RGB_ALPHA};
  const bool sixteen = pixels.depth() == CV_16U;
  png_set_IHDR(png, info, png_uint_32(pixels.cols), png_uint_32(pixels.rows), sixteen ? 16 : 8,
               colour_type[pixels.channels()], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (sixteen && little_endian()) png_set_swap(png);
  rows.resize(std::size_t(pixels.rows));
  for (int y = 0; y < pixels.rows; ++y) rows[std::size_t(y)] = const_cast<png_bytep>(pixels.ptr<png_byte>(y));
  png_write_image(png, rows.data());
  png_write_end(png, info);
  return true;
}

}  // namespace

cv::Mat decode_png(std::string_view bytes) {
  PngState state;
  state.in = bytes;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
  if (!png) throw runtime_failure("PNG reader: libpng could not start (out of memory)");
  png_infop info = png_create_info_struct(png);
  cv::Mat pixels;
  std::vector<png_bytep> rows;
  const bool ok = info && read_png(png, info, pixels, rows, state);
  png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
  if (!ok) throw bad_input("PNG data: {}", state.message[0] ? state.message : "corrupt or truncated pixel data");
  return pixels;
}

std::string encode_png(const cv::Mat& pixels, int level, int strategy, const ProgressFn& progress) {
  const int channels = pixels.channels();
  if (channels < 1 || channels > 4 || (pixels.depth() != CV_8U && pixels.depth() != CV_16U))
    throw runtime_failure("PNG writer: 1 to 4 channels of 8 or 16 bits expected");
  std::string out;
  PngState state;
  state.out = &out;
  state.progress = &progress;
  state.rows = png_uint_32(pixels.rows);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
  if (!png) throw runtime_failure("PNG writer: libpng could not start (out of memory)");
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows;
  const bool ok = info && write_png(png, info, pixels, rows, level, strategy, state);
  png_destroy_write_struct(&png, info ? &info : nullptr);
  if (!ok) throw runtime_failure("PNG writer: {}", state.message[0] ? state.message : "libpng failed");
  return out;
}

}  // namespace fest::formats::image_detail

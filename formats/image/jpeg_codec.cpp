// JPEG through libjpeg(-turbo) directly, with the settings OpenCV 4.6 used (so pixels
// and bytes are unchanged): decoding with the library's defaults (ISLOW DCT, fancy
// upsampling) to grey or RGB, no EXIF rotation; encoding with jpeg_set_defaults (JFIF
// header, 4:2:0 chroma) and jpeg_set_quality(q, baseline).
//
// libjpeg's default error handler calls exit() and its warnings go to stderr. Here an
// error records the library's message and longjmps back to the setjmp in this file,
// and so does a warning: libjpeg warns about corrupt data ("Premature end of JPEG file",
// "Corrupt JPEG data: N extraneous bytes") and carries on with made-up pixels, which a
// measurement pipeline must not accept silently, so a warning is bad input too.
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <jpeglib.h>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {
namespace {

struct JpegErrors {
  jpeg_error_mgr pub;  // first, so that a j_common_ptr's err points here too
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void on_error(j_common_ptr c) {
  auto* e = reinterpret_cast<JpegErrors*>(c->err);
  (*c->err->format_message)(c, e->message);
  std::longjmp(e->jump, 1);
}

void on_message(j_common_ptr c, int level) {
  if (level >= 0) return;  // trace messages
  on_error(c);             // warnings: corrupt data
}

void install(JpegErrors& e) {
  jpeg_std_error(&e.pub);
  e.pub.error_exit = on_error;
  e.pub.emit_message = on_message;
  e.message[0] = '\0';
}

bool read_jpeg(jpeg_decompress_struct& c, std::string_view bytes, cv::Mat& pixels, JpegErrors& errors) {
  if (setjmp(errors.jump)) return false;
  jpeg_create_decompress(&c);
  jpeg_mem_src(&c, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&c, TRUE);
  const bool grey = c.num_components == 1;
  c.out_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_start_decompress(&c);
  pixels.create(int(c.output_height), int(c.output_width), grey ? CV_8UC1 : CV_8UC3);
  while (c.output_scanline < c.output_height) {
    JSAMPROW row = pixels.ptr<JSAMPLE>(int(c.output_scanline));
    jpeg_read_scanlines(&c, &row, 1);
  }
  jpeg_finish_decompress(&c);
  return true;
}

bool write_jpeg(jpeg_compress_struct& c, const cv::Mat& pixels, int quality, unsigned char** buffer,
                unsigned long* size, JpegErrors& errors) {
  if (setjmp(errors.jump)) return false;
  jpeg_create_compress(&c);
  jpeg_mem_dest(&c, buffer, size);
  c.image_width = JDIMENSION(pixels.cols);
  c.image_height = JDIMENSION(pixels.rows);
  c.input_components = pixels.channels();
  c.in_color_space = pixels.channels() == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, quality, TRUE);
  jpeg_start_compress(&c, TRUE);
  while (c.next_scanline < c.image_height) {
    JSAMPROW row = const_cast<JSAMPLE*>(pixels.ptr<JSAMPLE>(int(c.next_scanline)));
    jpeg_write_scanlines(&c, &row, 1);
  }
  jpeg_finish_compress(&c);
  return true;
}

}  // namespace

cv::Mat decode_jpeg(std::string_view bytes) {
  jpeg_decompress_struct c{};
  JpegErrors errors;
  install(errors);
  c.err = &errors.pub;
  cv::Mat pixels;
  const bool ok = read_jpeg(c, bytes, pixels, errors);
  jpeg_destroy_decompress(&c);
  if (!ok) throw bad_input("JPEG data: {}", errors.message[0] ? errors.message : "corrupt or truncated pixel data");
  return pixels;
}

std::string encode_jpeg(const cv::Mat& pixels, int quality) {
  if (pixels.depth() != CV_8U || (pixels.channels() != 1 && pixels.channels() != 3))
    throw runtime_failure("JPEG writer: 8-bit grey or RGB expected");
  jpeg_compress_struct c{};
  JpegErrors errors;
  install(errors);
  c.err = &errors.pub;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  const bool ok = write_jpeg(c, pixels, quality, &buffer, &size, errors);
  jpeg_destroy_compress(&c);
  std::string out;
  if (ok) out.assign(reinterpret_cast<const char*>(buffer), size);
  std::free(buffer);
  if (!ok) throw runtime_failure("JPEG writer: {}", errors.message);
  return out;
}

}  // namespace fest::formats::image_detail

#pragma once
// The decoders and encoders behind image_io.cpp, one file each. Decoders receive bytes
// whose header has already been validated.

#include <string>
#include <string_view>
#include <vector>

#include "core/image.hpp"
#include "core/progress_fn.hpp"
#include "formats/image/exr_extras.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats::image_detail {

// PNG through libpng (png_codec.cpp): decodes to RGB(A), grey or grey + alpha;
// encodes 1, 3 or 4 channels with zlib `level` and `strategy` and adaptive filters,
// reporting (rows written, rows) to `progress`.
cv::Mat decode_png(std::string_view bytes);
std::string encode_png(const cv::Mat& pixels, int level, int strategy, const ProgressFn& progress = {});

// JPEG through libjpeg-turbo (jpeg_codec.cpp): 8-bit grey or RGB; quality 1-100.
cv::Mat decode_jpeg(std::string_view bytes);
std::string encode_jpeg(const cv::Mat& pixels, int quality);

// TIFF through libtiff (tiff_codec.cpp), compiled into libfest_tiff_plugin.so: callers in
// the host reach it through tiff_codec() (codec_plugins.hpp). `expected` is the checked
// header.
cv::Mat decode_tiff(std::string_view bytes, const ImageHeader& expected);
std::string encode_tiff(const cv::Mat& pixels);  // LZW for integers, uncompressed float

// PGM/PPM/PAM, both directions (netpbm_codec.cpp says why not OpenCV).
cv::Mat decode_netpbm(std::string_view bytes, const NetpbmLayout& layout);
std::string encode_pnm(const cv::Mat& pixels, bool ascii);  // P2/P3/P5/P6 by channels
std::string encode_pam(const cv::Mat& pixels);

// PFM (pfm_codec.cpp says why not OpenCV): grey or RGB float.
cv::Mat decode_pfm(std::string_view bytes, const NetpbmLayout& layout);
std::string encode_pfm(const cv::Mat& pixels);

// PNG with two channels (grey + alpha), written as before by fest's own encoder.
std::string encode_png_grey_alpha(const cv::Mat& pixels);
// PNG of 1-4 channels, 8 or 16 bits, rows unfiltered, zlib `level` and `strategy`
// (Z_HUFFMAN_ONLY for noisy raw data).
std::string encode_png_unfiltered(const cv::Mat& pixels, int level, int strategy);

// EXR through OpenEXR on in-memory streams (exr_codec.cpp), compiled into
// libfest_exr_plugin.so: callers in the host reach it through exr_codec()
// (codec_plugins.hpp), and the exr_extras.hpp calls through the last three.
cv::Mat decode_exr(std::string_view bytes);
std::string encode_exr(const cv::Mat& pixels, bool half, const ProgressFn& progress);  // (lines written, lines)
std::string exr_write_with_extras(const cv::Mat& rgb, const ExrExtras& extras, bool half);
cv::Mat exr_read_channel(std::string_view bytes, const std::string& name);
ExrExtras exr_read_attributes(std::string_view bytes);

}  // namespace fest::formats::image_detail

#pragma once
// The decoders and encoders behind image_io.cpp, one file each. Decoders receive bytes
// whose header has already been validated.

#include <string>
#include <string_view>
#include <vector>

#include "core/image.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats::image_detail {

// OpenCV (PNG, TIFF): decodes to RGB(A) order and checks the result matches
// `expected` (size, and depth unless the header could not know it).
cv::Mat decode_with_opencv(std::string_view bytes, const ImageHeader& expected, const char* what);
// Encodes RGB(A) pixels; `extension` picks OpenCV's encoder (".png", ".pfm", ".tiff").
std::string encode_with_opencv(const cv::Mat& rgb, const char* extension, const std::vector<int>& params);

// PGM/PPM/PAM, both directions (netpbm_codec.cpp says why not OpenCV).
cv::Mat decode_netpbm(std::string_view bytes, const NetpbmLayout& layout);
std::string encode_pnm(const cv::Mat& pixels, bool ascii);  // P2/P3/P5/P6 by channels
std::string encode_pam(const cv::Mat& pixels);

// PFM reading (pfm_codec.cpp says why not OpenCV); writing is OpenCV's.
cv::Mat decode_pfm(std::string_view bytes, const NetpbmLayout& layout);

// PNG with two channels (grey + alpha), which OpenCV's encoder refuses.
std::string encode_png_grey_alpha(const cv::Mat& pixels);
// PNG of 1-4 channels, 8 or 16 bits, rows unfiltered, zlib `level` and `strategy`
// (Z_HUFFMAN_ONLY for noisy raw data).
std::string encode_png_unfiltered(const cv::Mat& pixels, int level, int strategy);

// EXR through OpenEXR on in-memory streams.
cv::Mat decode_exr(std::string_view bytes);
std::string encode_exr(const cv::Mat& pixels, bool half);

}  // namespace fest::formats::image_detail

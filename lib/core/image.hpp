#pragma once
// The image type of fest: an OpenCV matrix plus what the matrix alone does not say.
//
// Channel order in memory is R, G, B(, A) -- not OpenCV's BGR; readers and writers
// swap at the file boundary so algorithms never have to remember which.
// Depths: CV_8U, CV_16U, CV_32F (1 to 4 channels).

#include <opencv2/core.hpp>

namespace fest {

enum class ColorSpace {
  srgb,    // 8/16-bit display-referred data (PNG, PNM, TIFF unless told otherwise)
  linear,  // scene-referred floating point (PFM, EXR)
};

const char* color_space_name(ColorSpace c) noexcept;

struct Image {
  cv::Mat pixels;
  ColorSpace color_space = ColorSpace::srgb;
};

inline const char* color_space_name(ColorSpace c) noexcept {
  return c == ColorSpace::linear ? "linear" : "srgb";
}

}  // namespace fest

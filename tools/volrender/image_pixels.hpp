#pragma once
// Images read for composite and --screen-mask (formats/image), as linear straight RGBA.

#include <string>
#include <vector>

#include "core/image.hpp"

namespace fest::volrender_tool {

// Reads an image file; bad_input naming the file when it is not an image.
Image load_image(const std::string& path);

// Linear (sRGB decoded), straight (not premultiplied) RGBA of every pixel, row by row;
// grey and grey-alpha images are spread over r, g, b; 8-bit, 16-bit or float samples.
std::vector<float> linear_rgba(const Image& image, const std::string& name);

}  // namespace fest::volrender_tool

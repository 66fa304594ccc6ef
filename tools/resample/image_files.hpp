#pragma once
// resample's image input and output, all through formats/image (the project layout): recognised by
// content, written atomically, the output format from --to, the -o extension, or the
// input's family.

#include <optional>
#include <string>

#include "commands.hpp"
#include "core/image.hpp"
#include "formats/detect.hpp"

namespace fest::resample_tool {

struct LoadedImage {
  fest::Image image;
  fest::formats::Format format;
};

LoadedImage load_image(const std::string& path);

// --depth as OpenCV depth; f16 sets `half`.
struct Depth {
  int cv_depth = -1;  // -1: not given
  bool half = false;
};
Depth depth_of(std::optional<OutputDepth> depth);

// Picks the output format: --to (or --format), else the -o path's extension, else PNG
// for integer images and PFM for float ones.
fest::formats::Format output_format(const std::optional<fest::formats::OutputFormat>& to, const std::string& path,
                                    int cv_depth);

// The depth a format can hold when --depth was not given: float formats get f32, TIFF
// keeps the image's depth, JPEG gets 8 bits, other integer formats keep an integer depth
// (8 when it is float).
int default_depth(fest::formats::Format f, int image_depth);

// `out` gives the JPEG quality and the alpha flattening (its path and format are not used).
void store_image(const fest::Image& image, const std::string& path, fest::formats::Format f, bool half,
                 const ImageOutput& out = ImageOutput{});

}  // namespace fest::resample_tool

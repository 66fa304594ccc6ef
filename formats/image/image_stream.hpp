#pragma once
// A stream of images: concatenated raw Netpbm frames (P5/P6/P7, what
// `ffmpeg -f image2pipe -c:v pgm -` writes) or concatenated PNG files, split into one
// byte range per frame. Any other single image is a stream of one frame.

#include <string_view>
#include <vector>

namespace fest::formats {

// Throws fest::Error (bad_input) for an empty stream, a truncated frame, ASCII Netpbm
// (its length cannot be known from the header) or trailing bytes that are no image;
// messages name the frame index.
std::vector<std::string_view> split_image_stream(std::string_view bytes);

}  // namespace fest::formats

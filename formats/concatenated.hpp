#pragma once
// Streams of files written one after another with nothing between them (image frames
// from `ffmpeg -f image2pipe`, fest frame streams of NRRD frames): each format knows the
// length of a frame from its header, so the stream splits by reading headers in turn.
// The walk is written once here; image/image_stream.cpp and
// volume_source/volume_source.cpp supply how one frame is read.

#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace fest::formats {

// read_frame(rest, index, length) reads the frame at the start of `rest` (the index-th)
// and sets `length` to the bytes it takes (at least one); it returns std::nullopt when
// what is left is no frame but may be ignored (trailing whitespace), and throws for
// anything else. Frames are returned in order.
template <class Frame, class ReadFrame>
std::vector<Frame> split_concatenated(std::string_view bytes, ReadFrame&& read_frame) {
  std::vector<Frame> frames;
  while (!bytes.empty()) {
    std::size_t length = 0;
    std::optional<Frame> frame = read_frame(bytes, frames.size(), length);
    if (!frame) break;
    frames.push_back(std::move(*frame));
    bytes.remove_prefix(length);
  }
  return frames;
}

}  // namespace fest::formats

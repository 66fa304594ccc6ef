#pragma once
// One dequeued V4L2 buffer -> fest::Image: the uncompressed formats through
// lib/capture/pixel_formats, MJPEG through formats/'s JPEG decoder (libjpeg-turbo, which
// supplies the default Huffman tables that UVC cameras leave out of their frames).
// A camera's bytes are untrusted: whatever they hold, the result is an image of the
// negotiated size or a bad_input error, never a crash (tests/fuzz/fuzz_v4l2_frame.cpp).

#include "capture/pixel_formats.hpp"
#include "core/image.hpp"

namespace fest::devices {

// Throws bad_input for a truncated or corrupt frame, for an MJPEG frame whose size is not
// the negotiated width x height, and for a format fest does not convert.
Image decode_v4l2_frame(const capture::RawFrame& frame);

// Whether decode_v4l2_frame takes the fourcc (the raw ones and MJPG).
bool is_supported_v4l2_format(std::uint32_t code);

}  // namespace fest::devices

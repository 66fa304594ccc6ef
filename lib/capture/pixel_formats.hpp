#pragma once
// The uncompressed pixel formats UVC and machine-vision cameras deliver through V4L2,
// unpacked to fest::Image (R,G,B order). Pure functions over bytes, no device access:
// devices/v4l2_camera.cpp hands them the contents of a dequeued buffer, and MJPEG frames
// go to formats/'s JPEG decoder instead (devices/v4l2_frame.cpp).
//
//   YUYV  Y0 Cb Y1 Cr per two pixels (4:2:2), BT.601 limited range -> 8-bit RGB
//   GREY  8-bit luma, already full range   -> 8-bit RGB (R = G = B)
//   RGB3  8-bit R,G,B                      -> 8-bit RGB, copied
//   Y16   16-bit little-endian grey        -> 16-bit grey, unconverted

#include <cstdint>
#include <string>
#include <string_view>

#include "core/image.hpp"

namespace fest::capture {

// A V4L2 fourcc: four ASCII characters, the first in the low byte (v4l2_fourcc()).
constexpr std::uint32_t fourcc(char a, char b, char c, char d) {
  return std::uint32_t(std::uint8_t(a)) | std::uint32_t(std::uint8_t(b)) << 8 |
         std::uint32_t(std::uint8_t(c)) << 16 | std::uint32_t(std::uint8_t(d)) << 24;
}
inline constexpr std::uint32_t fourcc_yuyv = fourcc('Y', 'U', 'Y', 'V');
inline constexpr std::uint32_t fourcc_mjpg = fourcc('M', 'J', 'P', 'G');
inline constexpr std::uint32_t fourcc_grey = fourcc('G', 'R', 'E', 'Y');
inline constexpr std::uint32_t fourcc_rgb3 = fourcc('R', 'G', 'B', '3');
inline constexpr std::uint32_t fourcc_y16 = fourcc('Y', '1', '6', ' ');

// "YUYV", "Y16" (trailing spaces dropped; unprintable bytes as '?').
std::string fourcc_name(std::uint32_t code);
// "Y16" -> 'Y','1','6',' '; an empty or longer-than-4 name gives 0.
std::uint32_t fourcc_from_name(std::string_view name);

// One frame as the driver laid it out: `stride` bytes from the start of one row to the
// next (V4L2's bytesperline), `bytes` the buffer's used part.
struct RawFrame {
  std::uint32_t fourcc = 0;
  int width = 0, height = 0;
  int stride = 0;
  std::string_view bytes;
};

// BT.601 limited range ("studio swing": Y in 16-235, Cb/Cr in 16-240 around 128) to
// 8-bit full-range R'G'B' (still gamma-encoded), clamped to 0-255:
//   R = 255/219 (Y-16)                               + 255/112 (1-Kr)       (Cr-128)
//   G = 255/219 (Y-16) - 255/112 (1-Kb) Kb/Kg (Cb-128) - 255/112 (1-Kr) Kr/Kg (Cr-128)
//   B = 255/219 (Y-16) + 255/112 (1-Kb)       (Cb-128)
// with Kr = 0.299, Kb = 0.114, Kg = 1 - Kr - Kb (ITU-R BT.601). Computed in 16.16 fixed
// point, rounded to nearest.
struct Rgb8 {
  std::uint8_t r, g, b;
};
Rgb8 bt601_limited_to_rgb(int y, int cb, int cr);

// The uncompressed formats above. Throws bad_input (naming the format) when the bytes
// cannot hold width x height pixels at `stride`, when the stride is shorter than a row,
// when YUYV's width is odd, or for a fourcc that is not one of them.
Image unpack_raw_frame(const RawFrame& frame);

// Whether unpack_raw_frame takes `code`.
bool is_raw_format(std::uint32_t code);
// Bytes of one row of `width` pixels (no padding) for a raw format; 0 for others.
int raw_row_bytes(std::uint32_t code, int width);

}  // namespace fest::capture

#include "capture/pixel_formats.hpp"

#include <algorithm>
#include <cstring>

#include "core/error.hpp"

namespace fest::capture {

namespace {

// BT.601 coefficients (pixel_formats.hpp) in 16.16 fixed point, derived from Kr and Kb
// at compile time so the numbers in the header are the only ones written down.
constexpr double kr = 0.299, kb = 0.114, kg = 1.0 - kr - kb;
constexpr double luma_scale = 255.0 / 219.0;   // Y 16..235 -> 0..255
constexpr double chroma_scale = 255.0 / 112.0; // (C-128) in -112..112 -> -255..255 before (1-K)
constexpr int fixed(double v) { return int(v * 65536.0 + (v < 0 ? -0.5 : 0.5)); }
constexpr int c_y = fixed(luma_scale);
constexpr int c_r_cr = fixed(chroma_scale * (1 - kr));
constexpr int c_g_cb = fixed(chroma_scale * (1 - kb) * kb / kg);
constexpr int c_g_cr = fixed(chroma_scale * (1 - kr) * kr / kg);
constexpr int c_b_cb = fixed(chroma_scale * (1 - kb));

inline std::uint8_t clamp_round(int fixed_value) {
  const int v = (fixed_value + 32768) >> 16;  // round half up (arithmetic shift floors)
  return std::uint8_t(std::clamp(v, 0, 255));
}

const char* format_label(std::uint32_t code) {
  switch (code) {
    case fourcc_yuyv: return "YUYV";
    case fourcc_grey: return "GREY";
    case fourcc_rgb3: return "RGB3";
    case fourcc_y16: return "Y16";
    default: return "?";
  }
}

void check_layout(const RawFrame& f) {
  const char* what = format_label(f.fourcc);
  if (f.width <= 0 || f.height <= 0)
    throw bad_input("{} frame: size {} x {} is not positive", what, f.width, f.height);
  if (f.width > 65535 || f.height > 65535)
    throw bad_input("{} frame: size {} x {} is larger than V4L2 allows", what, f.width, f.height);
  const int row = raw_row_bytes(f.fourcc, f.width);
  if (f.stride < row)
    throw bad_input("{} frame: {} bytes per line is shorter than a row of {} pixels ({} bytes)", what, f.stride,
                    f.width, row);
  const std::uint64_t need = std::uint64_t(f.stride) * std::uint64_t(f.height - 1) + std::uint64_t(row);
  if (f.bytes.size() < need)
    throw bad_input("{} frame: {} bytes, {} x {} pixels need {}", what, f.bytes.size(), f.width, f.height, need);
  if (f.fourcc == fourcc_yuyv && f.width % 2 != 0)
    throw bad_input("YUYV frame: width {} is odd (pixels come in pairs)", f.width);
}

}  // namespace

std::string fourcc_name(std::uint32_t code) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const char c = char((code >> (8 * i)) & 0xFF);
    s += (c >= 0x20 && c < 0x7F) ? c : '?';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::uint32_t fourcc_from_name(std::string_view name) {
  if (name.empty() || name.size() > 4) return 0;
  char c[4] = {' ', ' ', ' ', ' '};
  std::memcpy(c, name.data(), name.size());
  return fourcc(c[0], c[1], c[2], c[3]);
}

Rgb8 bt601_limited_to_rgb(int y, int cb, int cr) {
  const int l = c_y * (y - 16), u = cb - 128, v = cr - 128;
  return {clamp_round(l + c_r_cr * v), clamp_round(l - c_g_cb * u - c_g_cr * v), clamp_round(l + c_b_cb * u)};
}

bool is_raw_format(std::uint32_t code) {
  return code == fourcc_yuyv || code == fourcc_grey || code == fourcc_rgb3 || code == fourcc_y16;
}

int raw_row_bytes(std::uint32_t code, int width) {
  switch (code) {
    case fourcc_yuyv: return 2 * width;
    case fourcc_grey: return width;
    case fourcc_rgb3: return 3 * width;
    case fourcc_y16: return 2 * width;
    default: return 0;
  }
}

Image unpack_raw_frame(const RawFrame& f) {
  if (!is_raw_format(f.fourcc)) throw bad_input("camera frame: pixel format '{}' is not an uncompressed one fest unpacks", fourcc_name(f.fourcc));
  check_layout(f);
  const auto* base = reinterpret_cast<const std::uint8_t*>(f.bytes.data());
  Image image;
  image.color_space = ColorSpace::srgb;
  cv::Mat& m = image.pixels;
  if (f.fourcc == fourcc_y16) {
    m.create(f.height, f.width, CV_16UC1);
    for (int r = 0; r < f.height; ++r) {
      const std::uint8_t* in = base + std::size_t(r) * std::size_t(f.stride);
      auto* out = m.ptr<std::uint16_t>(r);
      for (int c = 0; c < f.width; ++c) out[c] = std::uint16_t(in[2 * c] | in[2 * c + 1] << 8);
    }
    return image;
  }
  m.create(f.height, f.width, CV_8UC3);
  for (int r = 0; r < f.height; ++r) {
    const std::uint8_t* in = base + std::size_t(r) * std::size_t(f.stride);
    auto* out = m.ptr<std::uint8_t>(r);
    switch (f.fourcc) {
      case fourcc_rgb3: std::memcpy(out, in, std::size_t(3) * std::size_t(f.width)); break;
      case fourcc_grey:
        for (int c = 0; c < f.width; ++c) out[3 * c] = out[3 * c + 1] = out[3 * c + 2] = in[c];
        break;
      default:  // YUYV: Y0 Cb Y1 Cr, both pixels share the pair's chroma
        for (int c = 0; c < f.width; c += 2, in += 4, out += 6) {
          const Rgb8 p0 = bt601_limited_to_rgb(in[0], in[1], in[3]);
          const Rgb8 p1 = bt601_limited_to_rgb(in[2], in[1], in[3]);
          out[0] = p0.r, out[1] = p0.g, out[2] = p0.b;
          out[3] = p1.r, out[4] = p1.g, out[5] = p1.b;
        }
    }
  }
  return image;
}

}  // namespace fest::capture

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

// The equations' terms for every 8-bit sample value, so that a pixel costs three table
// reads, three additions and three clamps (YUYV frames are 2 million pixels at 1080p).
// The luma term carries the +1/2 that rounds to nearest.
struct Bt601Tables {
  int luma[256], r_cr[256], g_cb_cr[256][2], b_cb[256];
  Bt601Tables() {
    for (int i = 0; i < 256; ++i) {
      luma[i] = c_y * (i - 16) + 32768;
      r_cr[i] = c_r_cr * (i - 128);
      g_cb_cr[i][0] = -c_g_cb * (i - 128);
      g_cb_cr[i][1] = -c_g_cr * (i - 128);
      b_cb[i] = c_b_cb * (i - 128);
    }
  }
};
const Bt601Tables& tables() {
  static const Bt601Tables t;
  return t;
}

inline std::uint8_t clamp_shift(int fixed_value) {
  const int v = fixed_value >> 16;  // arithmetic shift floors: with the +1/2, rounds half up
  return std::uint8_t(v < 0 ? 0 : v > 255 ? 255 : v);
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
  const Bt601Tables& t = tables();
  const int l = t.luma[y & 0xFF], u = cb & 0xFF, v = cr & 0xFF;
  return {clamp_shift(l + t.r_cr[v]), clamp_shift(l + t.g_cb_cr[u][0] + t.g_cb_cr[v][1]), clamp_shift(l + t.b_cb[u])};
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
      default: {  // YUYV: Y0 Cb Y1 Cr, both pixels share the pair's chroma
        const Bt601Tables& t = tables();
        for (int c = 0; c < f.width; c += 2, in += 4, out += 6) {
          const int dr = t.r_cr[in[3]], dg = t.g_cb_cr[in[1]][0] + t.g_cb_cr[in[3]][1], db = t.b_cb[in[1]];
          const int l0 = t.luma[in[0]], l1 = t.luma[in[2]];
          out[0] = clamp_shift(l0 + dr), out[1] = clamp_shift(l0 + dg), out[2] = clamp_shift(l0 + db);
          out[3] = clamp_shift(l1 + dr), out[4] = clamp_shift(l1 + dg), out[5] = clamp_shift(l1 + db);
        }
      }
    }
  }
  return image;
}

}  // namespace fest::capture

#include "sampling/float_image.hpp"

#include <cmath>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif
#include <cstring>
#include <cstdint>
#include <type_traits>

#include "core/error.hpp"
#include "sampling/sample_patterns.hpp"
#include "sampling/srgb.hpp"
#include "core/cpu_features.hpp"

namespace fest::sampling {

int alpha_channel(int channels) {
  if (channels == 2) return 1;
  if (channels == 4) return 3;
  return -1;
}

void check_supported(const Image& in) {
  const cv::Mat& m = in.pixels;
  if (m.empty() || m.rows <= 0 || m.cols <= 0) throw bad_input("resize: the input image is empty");
  if (m.dims != 2) throw bad_input("resize: the input is not a 2-D image ({} dimensions)", m.dims);
  if (m.channels() < 1 || m.channels() > 4)
    throw bad_input("resize: {} channels are not supported (1 to 4)", m.channels());
  const int d = m.depth();
  if (d != CV_8U && d != CV_16U && d != CV_32F)
    throw bad_input("resize: pixel depth {} is not supported (8-bit, 16-bit or 32-bit float)", d);
}

namespace {

// dst[i] = src[i] * scale for 8-bit codes; the AVX2 build widens 8 codes per instruction
// where the CPU has it. Conversion of a byte is exact and the product is one rounding on
// either path, so the values are identical.
template <typename T>
[[gnu::always_inline]] inline void scale_values(const T* src, std::size_t n, float scale, float* dst) {
  for (std::size_t i = 0; i < n; ++i) dst[i] = static_cast<float>(src[i]) * scale;
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void scale_bytes_avx2(const std::uint8_t* src, std::size_t n, float scale, float* dst) {
  scale_values(src, n, scale, dst);
}

// dst[i] = lut[src[i]] for whole groups of 8 codes (one gather each); returns how many
// values it did. A table lookup either way: the values are identical.
__attribute__((target("avx2"))) std::size_t lookup_bytes_avx2(const std::uint8_t* src, std::size_t n, const float* lut,
                                                              float* dst) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    long long eight;
    std::memcpy(&eight, src + i, sizeof eight);
    const __m256i codes = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(eight));
    _mm256_storeu_ps(dst + i, _mm256_i32gather_ps(lut, codes, 4));
  }
  return i;
}
#endif

template <typename T>
void scale_row(const T* src, std::size_t n, float scale, float* dst) {
#if defined(__x86_64__) && defined(__GNUC__)
  if constexpr (std::is_same_v<T, std::uint8_t>)
    if (cpu_has_avx2()) return scale_bytes_avx2(src, n, scale, dst);
#endif
  scale_values(src, n, scale, dst);
}

// `lut`: decoded values by code (integer input with sRGB decoding), else nullptr and the
// values are scaled; the table is fetched once per row, not per value.
template <typename T>
void decode_one_row(const cv::Mat& m, int y, const Encoding& enc, const float* lut, float scale, float* dst) {
  const int c = m.channels(), a = alpha_channel(c);
  const T* src = m.ptr<T>(y);
  if (!lut && (a < 0 || !enc.premultiply)) {  // plain values: one vectorisable loop
    scale_row(src, static_cast<std::size_t>(m.cols) * static_cast<std::size_t>(c), scale, dst);
    return;
  }
  if (a < 0) {  // sRGB codes without alpha: one lookup per value, no per-channel branches
    const std::size_t n = static_cast<std::size_t>(m.cols) * static_cast<std::size_t>(c);
    std::size_t i = 0;
#if defined(__x86_64__) && defined(__GNUC__)
    if constexpr (std::is_same_v<T, std::uint8_t>)
      if (cpu_has_avx2()) i = lookup_bytes_avx2(src, n, lut, dst);
#endif
    for (; i < n; ++i) dst[i] = lut[static_cast<std::size_t>(src[i])];
    return;
  }
  for (int x = 0; x < m.cols; ++x, src += c, dst += c) {
    for (int ch = 0; ch < c; ++ch) {
      const bool colour = ch != a;
      if (colour && lut)
        dst[ch] = lut[static_cast<std::size_t>(src[ch])];
      else
        dst[ch] = static_cast<float>(src[ch]) * scale;
    }
    if (enc.premultiply && a >= 0)
      for (int ch = 0; ch < c; ++ch)
        if (ch != a) dst[ch] *= dst[a];
  }
}

// Float input with sRGB decoding (--colorspace srgb on float data): per value.
void decode_float_row(const cv::Mat& m, int y, const Encoding& enc, float* dst) {
  const int c = m.channels(), a = alpha_channel(c);
  const float* src = m.ptr<float>(y);
  for (int x = 0; x < m.cols; ++x, src += c, dst += c) {
    for (int ch = 0; ch < c; ++ch) dst[ch] = (ch != a && enc.decode_srgb) ? srgb_to_linear(src[ch]) : src[ch];
    if (enc.premultiply && a >= 0)
      for (int ch = 0; ch < c; ++ch)
        if (ch != a) dst[ch] *= dst[a];
  }
}

// Triangular noise on [-½, ½] (the difference of two uniforms, halved): it decorrelates
// the rounding error from the signal without the noise floor of a wider dither.
float dither_noise(std::uint64_t seed, int x, int y, int ch) {
  const std::uint64_t h = hash64(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(ch));
  const double u1 = static_cast<double>(h >> 40) * 0x1.0p-24, u2 = static_cast<double>(h & 0xffffffu) * 0x1.0p-24;
  return static_cast<float>(0.5 * (u1 - u2));
}

template <typename T>
T quantise(float v, float max_code) {
  const float scaled = v * max_code + 0.5f;  // round half up: 127.5 -> 128
  if (!(scaled > 0)) return 0;                // also maps NaN to 0
  if (scaled >= max_code) return static_cast<T>(max_code);
  return static_cast<T>(scaled);  // truncation is floor here (scaled > 0), without a call
}

// quantise<std::uint8_t> over a row, written without branches so that it vectorises:
// the same round half up, saturation and NaN -> 0.
void quantise8_row(const float* src, std::size_t n, std::uint8_t* dst) {
  for (std::size_t i = 0; i < n; ++i) {
    float scaled = src[i] * 255.0f + 0.5f;
    scaled = scaled > 0 ? scaled : 0.0f;
    scaled = scaled < 255.0f ? scaled : 255.0f;
    dst[i] = static_cast<std::uint8_t>(static_cast<int>(scaled));
  }
}

}  // namespace

void decode_row(const cv::Mat& m, int y, const Encoding& enc, float* dst) {
  switch (m.depth()) {
    case CV_8U:
      return decode_one_row<std::uint8_t>(m, y, enc, enc.decode_srgb ? srgb8_table() : nullptr, 1.0f / 255, dst);
    case CV_16U:
      return decode_one_row<std::uint16_t>(m, y, enc, enc.decode_srgb ? srgb16_table() : nullptr, 1.0f / 65535, dst);
    default:
      if (enc.decode_srgb) return decode_float_row(m, y, enc, dst);
      return decode_one_row<float>(m, y, enc, nullptr, 1.0f, dst);
  }
}

FloatImage to_working(const Image& in, const Encoding& enc) {
  check_supported(in);
  const cv::Mat& m = in.pixels;
  FloatImage out(m.cols, m.rows, m.channels());
  for (int y = 0; y < m.rows; ++y) decode_row(m, y, enc, out.row(y));
  return out;
}

cv::Mat from_working(const FloatImage& img, int depth, const Encoding& enc) {
  const int c = img.channels, a = alpha_channel(c);
  cv::Mat out(img.height, img.width, CV_MAKETYPE(depth, c));
  if (depth == CV_8U && !enc.dither && (a < 0 || !enc.premultiply)) {
    // The common 8-bit case value by value: the sRGB encoding through thresholds
    // (linear_to_srgb8) instead of a pow() per value, with the same rounding.
    const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(c);
    for (int y = 0; y < img.height; ++y) {
      const float* src = img.row(y);
      std::uint8_t* dst = out.ptr<std::uint8_t>(y);
      if (enc.decode_srgb && a < 0)
        linear_to_srgb8_row(src, n, dst);
      else if (!enc.decode_srgb)
        quantise8_row(src, n, dst);
      else
        for (std::size_t i = 0; i < n; ++i)
          dst[i] = enc.decode_srgb && static_cast<int>(i % static_cast<std::size_t>(c)) != a ? linear_to_srgb8(src[i])
                                                                                            : quantise<std::uint8_t>(src[i], 255.0f);
    }
    return out;
  }
  if (depth == CV_32F && !enc.decode_srgb && (a < 0 || !enc.premultiply)) {  // the values as they are
    for (int y = 0; y < img.height; ++y)
      std::memcpy(out.ptr<float>(y), img.row(y), static_cast<std::size_t>(img.width) * static_cast<std::size_t>(c) * sizeof(float));
    return out;
  }
  std::vector<float> px(static_cast<std::size_t>(c));
  for (int y = 0; y < img.height; ++y) {
    const float* src = img.row(y);
    for (int x = 0; x < img.width; ++x, src += c) {
      for (int ch = 0; ch < c; ++ch) px[static_cast<std::size_t>(ch)] = src[ch];
      if (enc.premultiply && a >= 0) {
        const float alpha = px[static_cast<std::size_t>(a)];
        for (int ch = 0; ch < c; ++ch)
          if (ch != a) px[static_cast<std::size_t>(ch)] = alpha < 1e-6f ? 0.0f : px[static_cast<std::size_t>(ch)] / alpha;
      }
      if (enc.decode_srgb)
        for (int ch = 0; ch < c; ++ch)
          if (ch != a) px[static_cast<std::size_t>(ch)] = linear_to_srgb(px[static_cast<std::size_t>(ch)]);
      for (int ch = 0; ch < c; ++ch) {
        float v = px[static_cast<std::size_t>(ch)];
        if (enc.dither && depth != CV_32F) v += dither_noise(enc.seed, x, y, ch) / (depth == CV_8U ? 255.0f : 65535.0f);
        if (depth == CV_8U)
          out.ptr<std::uint8_t>(y)[x * c + ch] = quantise<std::uint8_t>(v, 255.0f);
        else if (depth == CV_16U)
          out.ptr<std::uint16_t>(y)[x * c + ch] = quantise<std::uint16_t>(v, 65535.0f);
        else
          out.ptr<float>(y)[x * c + ch] = v;
      }
    }
  }
  return out;
}

}  // namespace fest::sampling

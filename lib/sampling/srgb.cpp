#include "sampling/srgb.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/srgb.hpp"

namespace fest::sampling {

float srgb_to_linear(float c) { return static_cast<float>(fest::srgb_to_linear_unclamped(c)); }

float linear_to_srgb(float l) { return static_cast<float>(fest::linear_to_srgb_unclamped(l)); }

const float* srgb8_table() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(static_cast<float>(i / 255.0));
    return t;
  }();
  return table.data();
}

const float* srgb16_table() {
  static const auto table = [] {
    std::vector<float> t(65536);
    for (int i = 0; i < 65536; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(static_cast<float>(i / 65535.0));
    return t;
  }();
  return table.data();
}

namespace {

// The rounding of from_working for 8-bit codes, from a float in code units / 255.
int round_code8(float encoded) {
  const float scaled = encoded * 255.0f + 0.5f;
  if (!(scaled > 0)) return 0;
  if (scaled >= 255.0f) return 255;
  return static_cast<int>(std::floor(scaled));
}

int reference_code8(float l) { return round_code8(linear_to_srgb(l)); }

float float_from_bits(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

constexpr int coarse_steps = 4096;  // buckets of the coarse table over [0, 1]

struct Srgb8Encoder {
  std::array<float, 256> threshold{};  // threshold[k]: the smallest float with code >= k (k >= 1)
  std::array<std::uint8_t, coarse_steps + 1> start{};  // code at the bucket's lower end

  Srgb8Encoder() {
    // Non-negative floats order like their bit patterns: bisect the bits for each code.
    for (int k = 1; k < 256; ++k) {
      std::uint32_t lo = 0, hi = 0x7f800000u;  // code(0) = 0 < k <= 255 = code(+inf)
      while (hi - lo > 1) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        (reference_code8(float_from_bits(mid)) >= k ? hi : lo) = mid;
      }
      threshold[static_cast<std::size_t>(k)] = float_from_bits(hi);
    }
    for (int i = 0; i <= coarse_steps; ++i)
      start[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(reference_code8(static_cast<float>(i) / coarse_steps));
  }
};

const Srgb8Encoder& srgb8_encoder() {
  static const Srgb8Encoder e;
  return e;
}

}  // namespace

namespace {

inline std::uint8_t encode8(const Srgb8Encoder& e, float l) {
  if (!(l >= e.threshold[1])) return 0;  // also NaN
  // l * coarse_steps is exact and truncates down, so i / coarse_steps <= l and the code is
  // at least start[i].
  const int i = l >= 1.0f ? coarse_steps : static_cast<int>(l * coarse_steps);
  int code = e.start[static_cast<std::size_t>(i)];
  while (code < 255 && l >= e.threshold[static_cast<std::size_t>(code) + 1]) ++code;
  return static_cast<std::uint8_t>(code);
}

}  // namespace

std::uint8_t linear_to_srgb8(float l) { return encode8(srgb8_encoder(), l); }

void linear_to_srgb8_row(const float* src, std::size_t n, std::uint8_t* dst) {
  const Srgb8Encoder& e = srgb8_encoder();
  for (std::size_t i = 0; i < n; ++i) dst[i] = encode8(e, src[i]);
}

float srgb8_to_linear(std::uint8_t code) { return srgb8_table()[code]; }
float srgb16_to_linear(std::uint16_t code) { return srgb16_table()[code]; }

}  // namespace fest::sampling

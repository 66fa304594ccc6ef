#pragma once
// sRGB transfer functions (IEC 61966-2-1), for the decode and encode steps of docs/resample.md "Streaming".

#include <cstddef>
#include <cstdint>

namespace fest::sampling {

// lib/core/srgb.hpp's curve, unclamped (values beyond [0, 1] pass through filtering), in float.
float srgb_to_linear(float c);
float linear_to_srgb(float l);

// Table lookups for integer codes: decoding every pixel through pow() would dominate the
// cost of a small kernel.
float srgb8_to_linear(std::uint8_t code);
const float* srgb8_table();   // the 256 decoded values, for loops that look up many codes
const float* srgb16_table();  // the 65536 decoded values
float srgb16_to_linear(std::uint16_t code);

// The 8-bit code of a linear value: exactly floor(255 linear_to_srgb(l) + 0.5) saturated
// to [0, 255] (NaN -> 0), as from_working rounds, without a pow() per value. The encoding
// is monotone, so the code is the number of the 255 thresholds (the smallest float that
// reaches each code) at or below l; a coarse table gives the start of the count.
std::uint8_t linear_to_srgb8(float l);
void linear_to_srgb8_row(const float* src, std::size_t n, std::uint8_t* dst);  // n values

}  // namespace fest::sampling

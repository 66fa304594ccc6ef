#pragma once
// sRGB transfer functions (IEC 61966-2-1), as spec §2.4 steps 1 and 8 state them.

#include <cstdint>

namespace fest::sampling {

float srgb_to_linear(float c);
float linear_to_srgb(float l);

// Table lookups for integer codes: decoding every pixel through pow() would dominate the
// cost of a small kernel.
float srgb8_to_linear(std::uint8_t code);
const float* srgb8_table();   // the 256 decoded values, for loops that look up many codes
const float* srgb16_table();  // the 65536 decoded values
float srgb16_to_linear(std::uint16_t code);

}  // namespace fest::sampling

#pragma once
// Voxel values <-> the integers the wavelet codes (docs/volwave.md §3).
//
// The L-infinity guarantee comes from quantising in the voxel domain, before the
// transform: with step s, key = round((v - offset) / s) and v' = offset + s * key, so
// |v - v'| <= s / 2 for every voxel whatever the wavelet does afterwards, because the
// integer wavelet then codes the keys without loss (Ansari, Memon & Ceran's
// "near-lossless" L-infinity coding). For a bound E:
//   integer data: s = 2 floor(E) + 1 (odd, so v' stays an integer and |v - v'| <= floor(E));
//   float data:   s = 2E; voxels whose stored float still misses by more than E (the
//                 float rounding of v') are kept exactly as outliers.
// Lossless: integer-valued data codes its values; other float32 data codes the bits of
// each float, mapped to integers in value order, so decoding is bit-exact.

#include <cstdint>
#include <vector>

#include "core/volume.hpp"
#include "wavelet/lifting.hpp"

namespace fest::wavelet {

enum class KeyKind : std::uint8_t {
  scaled = 0,        // v = offset + step * key
  float32_bits = 1,  // key = the float's bits in value order
};

struct Quantiser {
  KeyKind kind = KeyKind::scaled;
  double step = 1.0;
  double offset = 0.0;
};

// The value a decoded key stands for, before the conversion to the stored type.
inline double key_value(const Quantiser& q, std::int64_t key) noexcept {
  return q.offset + q.step * static_cast<double>(key);
}
std::int64_t float_key(float f) noexcept;
float key_float(std::int64_t key) noexcept;

// What a value becomes when stored as `type` (the same rule as fest's volume writers:
// integers round half away from zero and clamp to the type's range, NaN -> 0; float32
// rounds to nearest, overflowing to infinity).
double stored_as(double value, ScalarType type) noexcept;

// Chooses the quantiser for an L-infinity bound E > 0. Throws bad_input for NaN or
// infinite voxels (no bound can hold for them) and for a bound so small against the
// value range that the keys would exceed 2^50.
Quantiser plan_max_error(const Volume& volume, double bound);
// A quantiser of the given step (float data, or integer data with any step).
Quantiser plan_step(const Volume& volume, double step);
// Lossless: integer keys where every value is an integer below 2^50 in magnitude, else
// float32 bits; throws bad_input for float64 values that float32 cannot hold.
Quantiser plan_lossless(const Volume& volume);

// The key of one value.
std::int64_t key_of(const Quantiser& q, double v) noexcept;
// Keys of every voxel (x fastest), `threads` >= 1.
std::vector<std::int64_t> quantise(const Volume& volume, const Quantiser& q, int threads);
// Values from keys, already converted to `type`.
void dequantise(const std::vector<std::int64_t>& keys, const Quantiser& q, ScalarType type,
                std::vector<double>& values, int threads);
// The same in place: `buffer` holds n int64 keys (their bytes) and is overwritten with
// their values (the decoder's one buffer for coefficients and voxels).
void dequantise_in_place(double* buffer, std::size_t n, const Quantiser& q, ScalarType type, int threads);
// The same, row by row (rows of `row_length` keys): outside its span a row holds only
// zero keys, which are not read (the inverse transform's row spans, lifting.hpp).
void dequantise_rows_in_place(double* buffer, std::size_t row_length, const std::vector<RowSpan>& row_spans,
                               const Quantiser& q, ScalarType type, int threads);

}  // namespace fest::wavelet

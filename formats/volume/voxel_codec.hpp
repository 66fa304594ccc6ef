#pragma once
// Raw voxel bytes <-> doubles for every ScalarType, in either byte order. Shared by the
// NIfTI, NRRD and MetaImage readers and writers, which differ only in their headers.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

// Decodes values.size() values of type `type` from the front of `data`, which the caller
// has checked holds at least values.size() * scalar_type_size(type) bytes.
void decode_voxels(std::string_view data, ScalarType type, bool big_endian, std::vector<double>& values);

// Encodes the values as `type`, converting each with storable_value().
std::string encode_voxels(const std::vector<double>& values, ScalarType type, bool big_endian);

// What a value becomes when stored as `type`. Integer targets: rounded to the nearest
// integer (halves away from zero), clamped to the type's range, NaN stored as 0.
// float32: rounded to the nearest float; finite values beyond its range become
// +-infinity (IEEE overflow), NaN stays NaN. float64: unchanged.
double storable_value(double value, ScalarType type) noexcept;

// Parses whitespace-separated text numbers (NRRD "ascii" encoding, MetaImage
// BinaryData = False) into values; throws bad_input naming `what` when there are too few
// or one is not a number.
void parse_text_voxels(std::string_view text, std::vector<double>& values, const char* what);

// The largest voxel count whose data a zlib stream of `compressed_bytes` could hold:
// deflate cannot expand beyond ~1032:1, so a header asking for more is lying.
std::uint64_t max_inflated_bytes(std::uint64_t compressed_bytes) noexcept;

// Inflates exactly `expected` bytes of zlib/gzip data after checking the claim is
// plausible for the compressed size. `what` names the format in messages.
std::string inflate_voxel_bytes(std::string_view compressed, std::uint64_t expected, const char* what);

}  // namespace fest::formats::volume_detail

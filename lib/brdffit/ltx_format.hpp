#pragma once
// The .ltx lumitexel file (ltx(5), docs/brdffit.md §4), little-endian, packed:
//
//   8 bytes  magic "LUMITEX1"
//   u32      length H of the header in bytes
//   H bytes  UTF-8 JSON header (object)
//   N x 48   lumitexels: p 3 x f32, n 3 x f32, triangle u32, home_image u16,
//            home_pixel 2 x f32, first_sample u64, count u16
//   M x 42   samples: image u16, u_world 3 x f32, v_world 3 x f32, r 3 x f32, weight f32
//
// The header always carries "format": "ltx", "version": 1, "mesh_sha256", "images",
// "lumitexels" (N), "samples" (M) and the two record layouts; writers add what they know
// (cameras, lights, counts of dropped points ...). Readers need only those keys.

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdffit/lumitexel.hpp"

namespace fest::brdffit {

inline constexpr char ltx_magic[9] = "LUMITEX1";
inline constexpr std::size_t ltx_lumitexel_bytes = 48;
inline constexpr std::size_t ltx_sample_bytes = 42;

// `header` is copied and completed with the keys above (taken from `set`, which wins on
// conflict). Throws fest::Error (bad_input) when a lumitexel's samples lie outside the
// sample array or a sample names an image the set does not list.
std::vector<std::uint8_t> encode_ltx(const LumitexelSet& set, const nlohmann::json& header);

// Parses a whole .ltx file; fills *header (when not null) with the JSON header. Throws
// fest::Error (bad_input) naming the byte offset for a wrong magic, a truncated or
// oversized file, a malformed header or inconsistent records.
LumitexelSet decode_ltx(const std::vector<std::uint8_t>& bytes, nlohmann::json* header);

}  // namespace fest::brdffit

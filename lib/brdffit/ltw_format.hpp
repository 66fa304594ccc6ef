#pragma once
// The .ltw weights file (ltw(5)): brdffit's own format for the
// result of `project`, so it lives with the algorithm as bytes in, bytes out.
//
//   8 bytes  magic "LUMIWGT1"
//   u32 LE   length H of the header
//   H bytes  UTF-8 JSON header: model, basis BRDFs, per-cluster basis index lists,
//            weight mode, basis_size, lumitexel count (+ what the caller adds)
//   records  per lumitexel: u16 LE cluster, then f32 LE weights, basis_size of them
//            (3 x basis_size, channel-major, in rgb mode)

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "brdffit/project.hpp"

namespace fest::brdffit {

// `extra` (an object) is merged into the header (e.g. mesh_sha256, errors).
std::string encode_ltw(const Projection& projection, const nlohmann::json& extra = nlohmann::json::object());

// Throws bad_input naming the byte offset for a wrong magic, a truncated file, a header
// that is not what encode_ltw writes, or an out-of-range cluster or weight.
Projection decode_ltw(std::string_view bytes, nlohmann::json* header = nullptr);

}  // namespace fest::brdffit

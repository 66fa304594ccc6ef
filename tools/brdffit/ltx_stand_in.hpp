#pragma once
// STAND-IN for the .ltx lumitexel file until the geometry side's lib/brdffit/ltx_format
// (encode_ltx / decode_ltx) is merged: the layout of specs/brdffit.md §3 (magic LUMITEX1,
// u32 header length, JSON header with counts, packed little-endian lumitexel records of
// 48 bytes and sample records of 42 bytes). At the merge, the two calls below are
// replaced by decode_ltx / encode_ltx and this file is deleted.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "brdffit/lumitexel.hpp"

namespace brdffit_tool {

fest::brdffit::LumitexelSet read_ltx_stand_in(std::string_view bytes, nlohmann::json* header = nullptr);
std::string write_ltx_stand_in(const fest::brdffit::LumitexelSet& set, nlohmann::json header = nlohmann::json::object());

}  // namespace brdffit_tool

#pragma once
// The lit scene as PLY (docs/radiosity.md §6): vertex x y z nx ny nz, float rad_r rad_g
// rad_b (B), float irr_r irr_g irr_b (H), uchar red green blue; face object_id (int) and
// level (uchar); header comments name the objects in id order.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "radiosity/model.hpp"
#include "radiosity/vertex_values.hpp"

namespace fest::radiosity_tool {

// All objects (object < 0) or one object.
std::string lit_ply(const radiosity::Model& model, const radiosity::VertexValues& vv,
                    const std::vector<std::array<std::uint8_t, 3>>& colours, int object = -1);

}  // namespace fest::radiosity_tool

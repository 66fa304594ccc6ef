#pragma once
// The JSON scene of lmfsim (spec §4) <-> fest::lmfsim::Scene. Strict: unknown keys,
// unknown names and wrong types are bad_input with the JSON path of the culprit.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lmfsim/model.hpp"

namespace lmfsim_tool {

// `mesh_loader` reads a mesh file named in a body (vertices, triangles).
using MeshLoader = std::function<void(const std::string& path, std::vector<fest::lmfsim::Vec3>&,
                                      std::vector<std::array<int, 3>>&)>;

fest::lmfsim::Scene scene_from_json(const nlohmann::json& doc, const MeshLoader& mesh_loader);

// Replaces the initial state of the bodies in `doc` (used by `assemble`).
void write_state(nlohmann::json& doc, const fest::lmfsim::Scene& scene, const std::vector<fest::lmfsim::Vec3>& pos,
                 const std::vector<fest::lmfsim::Quat>& quat, const std::vector<fest::lmfsim::Vec3>& vel,
                 const std::vector<fest::lmfsim::Vec3>& omega);

}  // namespace lmfsim_tool

#pragma once
// The JSON scene of lmfsim (lmfsim(1), DESCRIPTION) <-> Scene: a codec, no file I/O
// (a mesh named in a body is read by the caller's MeshLoader). Strict: unknown keys,
// unknown names and wrong types are bad_input with the JSON path of the culprit.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lmfsim/model.hpp"

namespace fest::lmfsim {

// `mesh_loader` reads a mesh file named in a body (vertices, triangles).
using MeshLoader = std::function<void(const std::string& path, std::vector<Vec3>&,
                                      std::vector<std::array<int, 3>>&)>;

Scene scene_from_json(const nlohmann::json& doc, const MeshLoader& mesh_loader);

// Replaces the initial state of the bodies in `doc` (used by `assemble`).
void write_state(nlohmann::json& doc, const Scene& scene, const std::vector<Vec3>& pos,
                 const std::vector<Quat>& quat, const std::vector<Vec3>& vel,
                 const std::vector<Vec3>& omega);

}  // namespace fest::lmfsim

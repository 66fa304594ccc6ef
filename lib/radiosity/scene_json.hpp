#pragma once
// The scene file of radiosity (docs/radiosity.md "Scene JSON"), a codec bytes <-> types:
//
//   {"units": "mm",
//    "objects": [{"name": "floor", "mesh": "floor.obj" | "vertices": [[x,y,z],...],
//                 "faces": [[i,j,k,...],...], "reflectance": [r,g,b], "emission": [r,g,b],
//                 "transform": [16 numbers, row-major]}],
//    "meshing": {"patch_size": L, "element_size": L}}
//
// Objects naming a mesh file come back with their path and no geometry: reading files is
// the tool's job. Unknown keys are refused (a misspelt key must not be ignored).

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiosity/scene.hpp"

namespace fest::radiosity {

struct SceneFile {
  Scene scene;
  std::vector<std::string> mesh_paths;                         // per object; empty: inline geometry
  std::vector<std::optional<std::array<double, 16>>> transforms;  // per object, row-major 4 x 4
};

// Throws fest::Error(bad_input) naming the JSON path of what is wrong.
SceneFile decode_scene_json(std::string_view text);

// Inline geometry only; numbers written so that they read back exactly.
std::string encode_scene_json(const Scene& scene);

// x' = M x (homogeneous, the last row must be 0 0 0 1 up to rounding; throws bad_input
// otherwise). Reverses face order when det(M) < 0 so that fronts stay fronts.
void apply_transform(SceneObject& object, const std::array<double, 16>& m);

}  // namespace fest::radiosity

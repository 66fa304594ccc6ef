#pragma once
// Reading a scene: the JSON document (lib/radiosity's codec) and the mesh files its
// objects name (formats/mesh), resolved against the scene file's folder.

#include <string>

#include "radiosity/scene.hpp"

namespace fest::radiosity_tool {

radiosity::Scene read_scene(const std::string& path);

}  // namespace fest::radiosity_tool

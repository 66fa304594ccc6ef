#pragma once
// cam.json and light.json <-> the camera and the point light (fest-capture(5), CAMERA and
// LIGHT; docs/brdffit.md §1): the views brdffit renders and fits, and the rig's entries.
// `where` names the document in messages (a file, or "rig.json, image 3").

#include <string>

#include <nlohmann/json.hpp>

#include "reflectance/camera.hpp"
#include "reflectance/render.hpp"

namespace fest::reflectance {

PinholeCamera camera_from_json(const nlohmann::json& j, const std::string& where);
nlohmann::json camera_to_json(const PinholeCamera& c);
PointLight light_from_json(const nlohmann::json& j, const std::string& where);
nlohmann::json light_to_json(const PointLight& l, const std::string& id = "");

}  // namespace fest::reflectance

#include "brdffit/rig_json.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "reflectance/view_json.hpp"

namespace fest::brdffit {

RigDocument decode_rig(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("images") || !j["images"].is_array())
    throw bad_input("a rig needs an \"images\" array ({})", where);
  if (j.value("version", 1) != 1) throw bad_input("rig version {} is not supported ({})", j.value("version", 0), where);
  RigDocument rig;
  rig.frame = j.value("frame", "mesh");
  if (j.contains("session") && j["session"].is_string()) rig.session = j["session"].get<std::string>();
  for (std::size_t k = 0; k < j["images"].size(); ++k) {
    const auto& e = j["images"][k];
    const std::string at = fmt::format("{}, image {}", where, k);
    if (!e.is_object() || !e.contains("file") || !e["file"].is_string())
      throw bad_input("rig image needs a \"file\" ({})", at);
    RigEntry img;
    img.file = e["file"].get<std::string>();
    if (e.contains("mask") && e["mask"].is_string()) {
      img.mask = e["mask"].get<std::string>();
      img.has_mask = true;
    }
    img.angle_index = e.value("angle_index", 0);
    img.angle_deg = e.value("angle_deg", 0.0);
    if (!e.contains("camera")) throw bad_input("rig image has no \"camera\" ({})", at);
    img.view.camera = reflectance::camera_from_json(e["camera"], at);
    if (e.contains("light")) {
      img.view.light = reflectance::light_from_json(e["light"], at);
      img.light_id = e["light"].value("id", "");
    }
    rig.images.push_back(img);
  }
  if (rig.images.empty()) throw bad_input("the rig lists no images ({})", where);
  return rig;
}

}  // namespace fest::brdffit

#include "brdffit/rig_json.hpp"

#include <fmt/format.h>

#include <climits>
#include <cmath>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "reflectance/view_json.hpp"

namespace fest::brdffit {
namespace {

// Optional fields, checked before they are read: nlohmann's value() throws its own
// exceptions for a wrong type, and a double too large for an int is undefined behaviour
// (fuzz_brdffit_json).
int int_or(const nlohmann::json& o, const char* key, int fallback, const std::string& at) {
  if (!o.contains(key)) return fallback;
  const auto& v = o[key];
  if (!v.is_number_integer() || v.get<long long>() < INT_MIN || v.get<long long>() > INT_MAX ||
      (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(INT_MAX)))
    throw bad_input("rig \"{}\" must be an integer, not {} ({})", key, quoted_bytes(v.dump()), at);
  return static_cast<int>(v.get<long long>());
}

double number_or(const nlohmann::json& o, const char* key, double fallback, const std::string& at) {
  if (!o.contains(key)) return fallback;
  const auto& v = o[key];
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw bad_input("rig \"{}\" must be a finite number, not {} ({})", key, quoted_bytes(v.dump()), at);
  return v.get<double>();
}

std::string string_or(const nlohmann::json& o, const char* key, const std::string& fallback, const std::string& at) {
  if (!o.contains(key)) return fallback;
  const auto& v = o[key];
  if (!v.is_string()) throw bad_input("rig \"{}\" must be a string, not {} ({})", key, quoted_bytes(v.dump()), at);
  return v.get<std::string>();
}

}  // namespace

RigDocument decode_rig(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("images") || !j["images"].is_array())
    throw bad_input("a rig needs an \"images\" array ({})", where);
  if (j.contains("version") && j["version"] != 1)
    throw bad_input("rig version {} is not supported ({})", quoted_bytes(j["version"].dump()), where);
  RigDocument rig;
  rig.frame = string_or(j, "frame", "mesh", where);
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
    img.angle_index = int_or(e, "angle_index", 0, at);
    img.angle_deg = number_or(e, "angle_deg", 0.0, at);
    if (!e.contains("camera")) throw bad_input("rig image has no \"camera\" ({})", at);
    img.view.camera = reflectance::camera_from_json(e["camera"], at);
    if (e.contains("light")) {
      img.view.light = reflectance::light_from_json(e["light"], at);
      img.light_id = string_or(e["light"], "id", "", at);
    }
    rig.images.push_back(img);
  }
  if (rig.images.empty()) throw bad_input("the rig lists no images ({})", where);
  return rig;
}

}  // namespace fest::brdffit

#include "session_manifest.hpp"

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::hdrmerge_tool {

using nlohmann::json;

namespace {

SessionShot shot_at(const json& shots, const json& index, const std::string& where) {
  if (!index.is_number_unsigned() || index.get<std::size_t>() >= shots.size())
    throw bad_input("sets: shot index {} out of range ({})", quoted_bytes(index.dump()), where);
  const std::size_t k = index.get<std::size_t>();
  const json& j = shots[k];
  if (!j.is_object()) throw bad_input("shots[{}] must be an object ({})", k, where);
  SessionShot s;
  try {
    s.file = j.at("file").get<std::string>();
    s.sha256 = j.at("sha256").get<std::string>();
    s.exposure_s = j.at("exposure_s").get<double>();
    // get<int> of a double too large for an int is undefined behaviour: check first.
    const json& ai = j.at("angle_index");
    if (!ai.is_number_integer() || ai.get<long long>() < 0 || ai.get<long long>() > 1000000)
      throw bad_input("shots[{}].angle_index must be an integer in [0, 1000000] ({})", k, where);
    s.angle_index = static_cast<int>(ai.get<long long>());
    s.angle_deg = j.at("angle_deg").get<double>();
  } catch (const json::exception& e) {
    throw bad_input("shots[{}]: {} ({})", k, json_failure_words(e.what(), 0, {}), where);
  }
  if (s.file.empty() || s.file.front() == '/' || s.file.find("..") != std::string::npos)
    throw bad_input("shots[{}].file must be a path inside the session ({})", k, where);
  return s;
}

}  // namespace

SessionManifest parse_session_manifest(const json& manifest, const std::string& where) {
  // Fields are type-checked before they are read: json::value() throws the JSON library's
  // own exception for a field of another type.
  if (!manifest.is_object() || !manifest.contains("version") || manifest["version"] != 1)
    throw bad_input("not a capture manifest, version 1 ({})", where);
  const auto text_field = [&](const char* key) {
    return manifest.contains(key) && manifest[key].is_string() ? manifest[key].get<std::string>() : std::string();
  };
  const std::string status = text_field("status");
  if (status != "complete")
    throw bad_input("the session is not complete (status \"{}\"): finish it with capture run --resume ({})", quoted_bytes(status), where);
  SessionManifest out;
  out.session = text_field("session");

  const json empty = json::array();
  const json& shots = manifest.contains("shots") ? manifest["shots"] : empty;
  if (!shots.is_array() || !manifest.contains("sets") || !manifest["sets"].is_array())
    throw bad_input("manifest needs arrays \"shots\" and \"sets\" ({})", where);
  for (const json& js : manifest["sets"]) {
    const std::size_t n = out.sets.size();
    ExposureSet s;
    if (!js.is_object() || !js.contains("shots") || !js["shots"].is_array() || !js.contains("light") || !js["light"].is_string())
      throw bad_input("sets[{}] needs \"light\" and \"shots\" ({})", n, where);
    s.light = js["light"].get<std::string>();
    // It names an output file (a000_<light>.exr): a plain name, never a path out of DIR.
    if (s.light.empty() || s.light.find_first_of("/\\") != std::string::npos || s.light == "." || s.light == "..")
      throw bad_input("sets[{}].light \"{}\" is not a light id ({})", n, quoted_bytes(s.light), where);
    for (const json& i : js["shots"]) {
      SessionShot shot = shot_at(shots, i, where);
      if (s.exposures.empty() || shot.exposure_s != s.exposures.back().front().exposure_s) s.exposures.emplace_back();
      s.exposures.back().push_back(std::move(shot));
    }
    if (s.exposures.size() < 2)
      throw bad_input("sets[{}] has {} exposure(s), at least 2 are needed ({})", n, s.exposures.size(), where);
    s.angle_index = s.exposures.front().front().angle_index;
    s.angle_deg = s.exposures.front().front().angle_deg;
    out.sets.push_back(std::move(s));
  }
  if (out.sets.empty()) throw bad_input("the manifest has no exposure set ({})", where);
  // Silhouette shots, one per angle (the first one at that angle).
  for (std::size_t i = 0; i < shots.size(); ++i)
    if (shots[i].is_object() && shots[i].contains("kind") && shots[i]["kind"] == "silhouette") {
      const SessionShot s = shot_at(shots, json(i), where);
      out.silhouettes.emplace(s.angle_index, s);
    }
  return out;
}

}  // namespace fest::hdrmerge_tool

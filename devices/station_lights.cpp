#include "devices/station_lights.hpp"

#include <algorithm>

#include <cstdlib>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/quote.hpp"

namespace fest::devices {

std::string station_path(const std::string& flag) {
  if (!flag.empty()) return flag;
  const char* env = std::getenv("CAPTURE_STATION");
  return env ? env : "";
}

nlohmann::json read_station(const std::string& path) {
  const std::string text = read_input(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw bad_input("station: {}", with_location(json_failure_words(e.what(), e.byte, text), path));
  }
}

std::vector<LightConfig> lights_from_station(const nlohmann::json& station, const std::string& where) {
  static const std::vector<std::string> known = {"id",        "uri",     "active_low", "position_mm",
                                                 "intensity", "warmup_ms", "max_on_s",  "role"};
  if (!station.is_object()) throw bad_input("a station must be a JSON object ({})", where);
  const auto it = station.find("lights");
  if (it == station.end()) throw bad_input("the station has no \"lights\" array ({})", where);
  if (!it->is_array()) throw bad_input("\"lights\" must be an array ({}: /lights)", where);
  std::vector<LightConfig> out;
  for (std::size_t i = 0; i < it->size(); ++i) {
    const nlohmann::json& l = (*it)[i];
    const std::string path = fmt::format("/lights/{}", i);
    if (!l.is_object()) throw bad_input("a light must be an object ({}: {})", where, path);
    for (const auto& item : l.items())
      if (std::find(known.begin(), known.end(), item.key()) == known.end())
        throw bad_input("unknown key \"{}\" in a light (known: {}) ({}: {})", item.key(), fmt::join(known, ", "), where, path);
    LightConfig c;
    const auto id = l.find("id"), uri = l.find("uri"), low = l.find("active_low");
    if (id == l.end() || !id->is_string() || id->get<std::string>().empty())
      throw bad_input("a light needs a non-empty string \"id\" ({}: {}/id)", where, path);
    if (uri == l.end() || !uri->is_string()) throw bad_input("a light needs a string \"uri\" ({}: {}/uri)", where, path);
    if (low != l.end() && !low->is_boolean()) throw bad_input("\"active_low\" must be true or false ({}: {}/active_low)", where, path);
    c.id = id->get<std::string>();
    c.uri = uri->get<std::string>();
    c.active_low = low != l.end() && low->get<bool>();
    if (std::any_of(out.begin(), out.end(), [&](const LightConfig& o) { return o.id == c.id; }))
      throw bad_input("light id \"{}\" appears twice ({}: {}/id)", c.id, where, path);
    out.push_back(c);
  }
  return out;
}

}  // namespace fest::devices

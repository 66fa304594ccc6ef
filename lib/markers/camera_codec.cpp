#include "markers/camera_codec.hpp"
#include "core/quote.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace fest::markers {

using nlohmann::json;

namespace {

double finite_number(const json& v, const std::string& what) {
  if (!v.is_number()) throw bad_input("camera: {} is not a number", what);
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw bad_input("camera: {} is not finite", what);
  return x;
}

}  // namespace

CameraModel decode_camera_json(std::string_view text) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // json_failure_words says "not JSON: <what> at line L, column C (byte B)".
    throw bad_input("camera: not valid JSON: {}", json_failure_words(e.what(), e.byte, text).substr(10));
  } catch (const json::exception& e) {
    throw bad_input("camera: not valid JSON: {}", json_failure_words(e.what(), 0, text));
  }
  if (!doc.is_object()) throw bad_input("camera: not a JSON object");
  CameraModel c;
  if (!doc.contains("K") || !doc["K"].is_array() || doc["K"].size() != 9)
    throw bad_input("camera: 'K' must hold 9 numbers");
  for (std::size_t i = 0; i < 9; ++i) c.K.val[i] = finite_number(doc["K"][i], fmt::format("K[{}]", i));
  if (doc.contains("dist")) {
    const json& d = doc["dist"];
    if (!d.is_array() || d.size() > 5) throw bad_input("camera: 'dist' must hold up to 5 numbers");
    for (std::size_t i = 0; i < d.size(); ++i) c.dist[int(i)] = finite_number(d[i], fmt::format("dist[{}]", i));
  }
  for (const char* key : {"width", "height"})
    if (!doc.contains(key)) throw bad_input("camera: '{}' missing", key);
  const double w = finite_number(doc["width"], "width"), h = finite_number(doc["height"], "height");
  if (w < 1 || h < 1 || w > 1e6 || h > 1e6 || w != std::floor(w) || h != std::floor(h))
    throw bad_input("camera: width and height must be positive integers");
  c.width = static_cast<int>(w);
  c.height = static_cast<int>(h);
  if (!(c.K(0, 0) > 0) || !(c.K(1, 1) > 0) || c.K(2, 2) != 1 || c.K(1, 0) != 0 || c.K(2, 0) != 0 || c.K(2, 1) != 0)
    throw bad_input("camera: K must be [fx s cx; 0 fy cy; 0 0 1] with positive focal lengths");
  return c;
}

std::string encode_camera_json(const CameraModel& c) {
  json k = json::array(), d = json::array();
  for (int i = 0; i < 9; ++i) k.push_back(c.K.val[i]);
  for (int i = 0; i < 5; ++i) d.push_back(c.dist[i]);
  json doc = {{"K", k},
              {"dist", d},
              {"R", {1, 0, 0, 0, 1, 0, 0, 0, 1}},
              {"t", {0, 0, 0}},
              {"width", c.width},
              {"height", c.height}};
  return doc.dump(2) + "\n";
}

}  // namespace fest::markers

#include "reflectance/view_json.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace fest::reflectance {
namespace {

std::vector<double> numbers(const nlohmann::json& j, const char* key, std::size_t n, const std::string& where) {
  if (!j.contains(key) || !j[key].is_array() || j[key].size() != n)
    throw bad_input("\"{}\" must be an array of {} numbers ({})", key, n, where);
  std::vector<double> v;
  for (const auto& x : j[key]) {
    if (!x.is_number()) throw bad_input("\"{}\" must be an array of {} numbers ({})", key, n, where);
    v.push_back(x.get<double>());
    if (!std::isfinite(v.back())) throw bad_input("\"{}\" holds a non-finite number ({})", key, where);
  }
  return v;
}

}  // namespace

PinholeCamera camera_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw bad_input("a camera must be a JSON object ({})", where);
  PinholeCamera c;
  const auto K = numbers(j, "K", 9, where);
  c.fx = K[0];
  c.cx = K[2];
  c.fy = K[4];
  c.cy = K[5];
  if (!(c.fx > 0 && c.fy > 0)) throw bad_input("camera focal lengths must be positive ({})", where);
  if (j.contains("dist")) {
    const auto d = numbers(j, "dist", 5, where);
    for (int k = 0; k < 5; ++k) c.dist[static_cast<std::size_t>(k)] = d[static_cast<std::size_t>(k)];
  }
  const auto R = numbers(j, "R", 9, where);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c.R(r, k) = R[static_cast<std::size_t>(3 * r + k)];
  if ((c.R * c.R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-5 || c.R.determinant() < 0)
    throw bad_input("camera \"R\" is not a rotation ({})", where);
  const auto t = numbers(j, "t", 3, where);
  c.t = Eigen::Vector3d(t[0], t[1], t[2]);
  if (!j.contains("width") || !j.contains("height") || !j["width"].is_number_integer() ||
      !j["height"].is_number_integer())
    throw bad_input("camera needs integer \"width\" and \"height\" ({})", where);
  // Read wide and checked before narrowing: 4294967297 must not become a width of 1.
  const long long w = j["width"].get<long long>(), h = j["height"].get<long long>();
  if (w < 1 || h < 1 || w > 65536 || h > 65536)
    throw bad_input("camera size {}x{} is not plausible ({})", j["width"].dump(), j["height"].dump(), where);
  c.width = static_cast<int>(w);
  c.height = static_cast<int>(h);
  return c;
}

nlohmann::json camera_to_json(const PinholeCamera& c) {
  nlohmann::json j;
  j["K"] = {c.fx, 0.0, c.cx, 0.0, c.fy, c.cy, 0.0, 0.0, 1.0};
  j["dist"] = c.dist;
  std::vector<double> R;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) R.push_back(c.R(r, k));
  j["R"] = R;
  j["t"] = {c.t.x(), c.t.y(), c.t.z()};
  j["width"] = c.width;
  j["height"] = c.height;
  return j;
}

PointLight light_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw bad_input("a light must be a JSON object ({})", where);
  PointLight l;
  const auto p = numbers(j, "position", 3, where);
  l.position = Eigen::Vector3d(p[0], p[1], p[2]);
  const auto i = numbers(j, "intensity", 3, where);
  l.intensity = Rgb(i[0], i[1], i[2]);
  if (!(l.intensity.minCoeff() > 0)) throw bad_input("light intensity must be positive ({})", where);
  return l;
}

nlohmann::json light_to_json(const PointLight& l, const std::string& id) {
  nlohmann::json j;
  if (!id.empty()) j["id"] = id;
  j["position"] = {l.position.x(), l.position.y(), l.position.z()};
  j["intensity"] = {l.intensity.x(), l.intensity.y(), l.intensity.z()};
  return j;
}

}  // namespace fest::reflectance

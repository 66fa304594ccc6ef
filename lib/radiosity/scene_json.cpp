#include "radiosity/scene_json.hpp"
#include "core/quote.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace fest::radiosity {
namespace {

using json = nlohmann::json;

void only_keys(const json& j, std::initializer_list<const char*> keys, const std::string& where) {
  const std::set<std::string> allowed(keys.begin(), keys.end());
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!allowed.count(it.key())) throw bad_input("scene: unknown key \"{}\" ({})", it.key(), where);
}

double number(const json& j, const std::string& where) {
  if (!j.is_number()) throw bad_input("scene: expected a number ({})", where);
  return j.get<double>();
}

Rgb rgb(const json& j, const std::string& where) {
  if (j.is_number()) return Rgb::Constant(j.get<double>());
  if (!j.is_array() || j.size() != 3) throw bad_input("scene: expected [r, g, b] ({})", where);
  return Rgb(number(j[0], where + "/0"), number(j[1], where + "/1"), number(j[2], where + "/2"));
}

}  // namespace

SceneFile decode_scene_json(std::string_view text) {
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw bad_input("scene: {}", json_failure_words(e.what(), e.byte, text));
  } catch (const json::exception& e) {
    throw bad_input("scene: {}", json_failure_words(e.what(), 0, text));
  }
  if (!root.is_object()) throw bad_input("scene: the top level must be an object");
  only_keys(root, {"units", "objects", "meshing"}, "/");
  SceneFile out;
  if (root.contains("units")) {
    if (!root["units"].is_string()) throw bad_input("scene: units must be a string (/units)");
    out.scene.units = root["units"].get<std::string>();
  }
  if (root.contains("meshing")) {
    const json& m = root["meshing"];
    if (!m.is_object()) throw bad_input("scene: meshing must be an object (/meshing)");
    only_keys(m, {"patch_size", "element_size"}, "/meshing");
    if (m.contains("patch_size")) out.scene.patch_size = number(m["patch_size"], "/meshing/patch_size");
    if (m.contains("element_size")) out.scene.element_size = number(m["element_size"], "/meshing/element_size");
    if (!(out.scene.patch_size >= 0) || !(out.scene.element_size >= 0) || !std::isfinite(out.scene.patch_size) ||
        !std::isfinite(out.scene.element_size))
      throw bad_input("scene: meshing sizes must be finite and positive (/meshing)");
  }
  if (!root.contains("objects") || !root["objects"].is_array()) throw bad_input("scene: no \"objects\" array (/)");
  const json& objs = root["objects"];
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const std::string where = "/objects/" + std::to_string(i);
    const json& o = objs[i];
    if (!o.is_object()) throw bad_input("scene: an object must be a JSON object ({})", where);
    only_keys(o, {"name", "mesh", "vertices", "faces", "reflectance", "emission", "texture", "transform"}, where);
    if (o.contains("texture"))
      throw bad_input("scene: textures are not supported; remove \"texture\" or bake it into the reflectance ({})",
                      where);
    SceneObject so;
    so.name = "object" + std::to_string(i);
    if (o.contains("name")) {
      if (!o["name"].is_string()) throw bad_input("scene: name must be a string ({}/name)", where);
      so.name = o["name"].get<std::string>();
    }
    if (!o.contains("reflectance")) throw bad_input("scene: no reflectance ({})", where);
    so.reflectance = rgb(o["reflectance"], where + "/reflectance");
    if (o.contains("emission")) so.emission = rgb(o["emission"], where + "/emission");
    std::string path;
    if (o.contains("mesh")) {
      if (!o["mesh"].is_string()) throw bad_input("scene: mesh must be a file name ({}/mesh)", where);
      if (o.contains("vertices") || o.contains("faces"))
        throw bad_input("scene: give either \"mesh\" or \"vertices\" and \"faces\" ({})", where);
      path = o["mesh"].get<std::string>();
    } else {
      if (!o.contains("vertices") || !o.contains("faces") || !o["vertices"].is_array() || !o["faces"].is_array())
        throw bad_input("scene: an object needs \"mesh\" or \"vertices\" and \"faces\" arrays ({})", where);
      const json& vs = o["vertices"];
      for (std::size_t v = 0; v < vs.size(); ++v) {
        const std::string w = where + "/vertices/" + std::to_string(v);
        if (!vs[v].is_array() || vs[v].size() != 3) throw bad_input("scene: a vertex is [x, y, z] ({})", w);
        so.vertices.emplace_back(number(vs[v][0], w), number(vs[v][1], w), number(vs[v][2], w));
      }
      const json& fs = o["faces"];
      for (std::size_t f = 0; f < fs.size(); ++f) {
        const std::string w = where + "/faces/" + std::to_string(f);
        if (!fs[f].is_array()) throw bad_input("scene: a face is a list of vertex indices ({})", w);
        std::vector<std::uint32_t> face;
        for (const json& idx : fs[f]) {
          if (!idx.is_number_integer() || idx.get<long long>() < 0 || idx.get<long long>() > 0xffffffffLL)
            throw bad_input("scene: a vertex index must be a non-negative integer ({})", w);
          face.push_back(static_cast<std::uint32_t>(idx.get<long long>()));
        }
        so.faces.push_back(std::move(face));
      }
    }
    std::optional<std::array<double, 16>> transform;
    if (o.contains("transform")) {
      const json& t = o["transform"];
      if (!t.is_array() || t.size() != 16) throw bad_input("scene: transform is 16 numbers, row-major ({}/transform)", where);
      std::array<double, 16> m{};
      for (int k = 0; k < 16; ++k) m[k] = number(t[k], where + "/transform");
      transform = m;
      if (path.empty()) apply_transform(so, m);
    }
    out.scene.objects.push_back(std::move(so));
    out.mesh_paths.push_back(path);
    out.transforms.push_back(transform);
  }
  return out;
}

std::string encode_scene_json(const Scene& scene) {
  json root;
  root["units"] = scene.units;
  json objs = json::array();
  for (const SceneObject& o : scene.objects) {
    json j;
    j["name"] = o.name;
    j["reflectance"] = {o.reflectance[0], o.reflectance[1], o.reflectance[2]};
    j["emission"] = {o.emission[0], o.emission[1], o.emission[2]};
    json vs = json::array();
    for (const auto& v : o.vertices) vs.push_back({v.x(), v.y(), v.z()});
    j["vertices"] = vs;
    j["faces"] = o.faces;
    objs.push_back(j);
  }
  root["objects"] = objs;
  if (scene.patch_size > 0 || scene.element_size > 0) {
    json m = json::object();
    if (scene.patch_size > 0) m["patch_size"] = scene.patch_size;
    if (scene.element_size > 0) m["element_size"] = scene.element_size;
    root["meshing"] = m;
  }
  return root.dump(1) + "\n";
}

void apply_transform(SceneObject& o, const std::array<double, 16>& m) {
  for (double v : m)
    if (!std::isfinite(v)) throw bad_input("object '{}': transform is not finite", o.name);
  if (std::abs(m[12]) > 1e-12 || std::abs(m[13]) > 1e-12 || std::abs(m[14]) > 1e-12 || std::abs(m[15] - 1) > 1e-12)
    throw bad_input("object '{}': transform's last row must be 0 0 0 1 (no projective transforms)", o.name);
  Eigen::Matrix3d a;
  a << m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10];
  const Eigen::Vector3d t(m[3], m[7], m[11]);
  for (auto& v : o.vertices) v = a * v + t;
  if (a.determinant() < 0)
    for (auto& f : o.faces) std::reverse(f.begin(), f.end());
}

}  // namespace fest::radiosity

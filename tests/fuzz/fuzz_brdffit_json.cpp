// brdffit's JSON inputs as loaded into their types, every decoder fed the same document:
// the rig file (lib/brdffit/rig_json: decode_rig), cam.json and light.json
// (lib/reflectance/view_json; what decodes must encode and decode again), brdf.json, the
// model and clusters.json (lib/brdffit/brdf_json), and the materials file against a
// two-triangle mesh (tools/brdffit/scene_io: materials_from_json). Each must give its type
// or a clean fest::Error; a decoded camera must also survive its own round trip.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "brdffit/brdf_json.hpp"
#include "brdffit/rig_json.hpp"
#include "core/error.hpp"
#include "reflectance/view_json.hpp"
#include "scene_io.hpp"

namespace {

template <class F>
void clean(F&& f) {
  try {
    f();
  } catch (const fest::Error&) {
  }
}

const fest::reflectance::TriangleMesh& square() {
  static const fest::reflectance::TriangleMesh m = [] {
    fest::reflectance::TriangleMesh t;
    t.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    t.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    fest::reflectance::compute_vertex_normals(t);
    return t;
  }();
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
  if (doc.is_discarded()) return 0;
  clean([&] { brdffit::decode_rig(doc, "rig.json"); });
  clean([&] {
    const auto cam = reflectance::camera_from_json(doc, "cam.json");
    try {
      reflectance::camera_from_json(reflectance::camera_to_json(cam), "round trip");
    } catch (const Error&) {
      __builtin_trap();  // a camera the codec accepted must read back
    }
  });
  clean([&] {
    const auto light = reflectance::light_from_json(doc, "light.json");
    try {
      reflectance::light_from_json(reflectance::light_to_json(light), "round trip");
    } catch (const Error&) {
      __builtin_trap();
    }
  });
  clean([&] { brdffit::brdf_from_json(doc); });
  clean([&] { brdffit::model_from_json(doc); });
  clean([&] { brdffit::clusters_from_json(doc); });
  clean([&] { brdffit_tool::materials_from_json(doc, square(), "materials.json"); });
  return 0;
}

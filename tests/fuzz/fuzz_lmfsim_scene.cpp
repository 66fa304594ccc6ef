// lmfsim's scene JSON codec (lib/lmfsim/scene_json: scene_from_json) and the scene checks
// every run starts with (validate_scene). A body naming a mesh gets a closed tetrahedron
// (the tool's loader reads the file; reading is not under test). Any bytes must give a
// valid scene or a clean fest::Error.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "lmfsim/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest::lmfsim;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
  if (doc.is_discarded()) return 0;
  const MeshLoader tetrahedron = [](const std::string& path, std::vector<Vec3>& v, std::vector<std::array<int, 3>>& t) {
    if (path.empty()) throw fest::bad_input("empty mesh path");
    v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  };
  try {
    Scene scene = scene_from_json(doc, tetrahedron);
    validate_scene(scene);
  } catch (const fest::Error&) {
  }
  return 0;
}

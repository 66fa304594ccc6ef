// radiosity's scene inputs: the JSON codec (lib/radiosity/scene_json.hpp) and the PLY
// with per-face properties (formats/mesh/attributed_ply.hpp), then the scene checks:
// any bytes must give a scene or fest::Error, never a crash or a hang. Small accepted
// JSON scenes are also meshed (one patch per face).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/mesh/attributed_ply.hpp"
#include "radiosity/scene.hpp"
#include "radiosity/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    if (bytes.substr(0, 3) == "ply") {
      fest::formats::read_attributed_ply(bytes);
      return 0;
    }
    const auto file = fest::radiosity::decode_scene_json(bytes);
    std::size_t faces = 0;
    for (const auto& o : file.scene.objects) faces += o.faces.size();
    if (faces > 64) return 0;
    fest::radiosity::MeshingOptions m;
    m.no_mesh = true;
    fest::radiosity::build_model(file.scene, m);
  } catch (const fest::Error&) {
  }
  return 0;
}

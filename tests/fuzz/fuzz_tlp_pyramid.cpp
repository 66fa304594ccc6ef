// A terrainlod pyramid as the tool opens it (tools/terrainlod/pyramid_file: PyramidFile
// over an archive's bytes): the .tlp head and index, the manifest JSON and its checks, the
// index against the pyramid's layout, then every tile's header (z_range) and the tile
// itself (lib/terrainlod/tile_codec: decode_tile, progressive tiles against their decoded
// parents). Bytes that are no archive are decoded as one standalone .tlt tile, and a JSON
// object as an extraction camera (parse_camera). Anything must end in a pyramid, a tile
// or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "pyramid_file.hpp"
#include "pyramid_view.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/tlp_archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fest;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    if (terrainlod::looks_like_tlp(bytes)) {
      terrainlod_tool::PyramidFile pyr{std::string(bytes), "fuzz.tlp"};
      for (const auto& e : pyr.index()) {
        pyr.z_range(e.id);
        pyr.tile(e.id);
        if (pyr.textured()) pyr.texture_bytes(e.id);
      }
      return 0;
    }
    if (!bytes.empty() && bytes.front() == '{') {
      const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
      if (!doc.is_discarded()) terrainlod_tool::parse_camera(doc, "camera");
      return 0;
    }
    terrainlod::read_tile_header(bytes);
    terrainlod::decode_tile(bytes);
  } catch (const Error&) {
  }
  return 0;
}

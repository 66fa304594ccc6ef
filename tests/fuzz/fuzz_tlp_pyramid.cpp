// A terrainlod pyramid as the tool opens it (tools/terrainlod/pyramid_file: PyramidFile
// over an archive's bytes): the .tlp head and index, the manifest JSON and its checks, the
// index against the pyramid's layout, then every tile's header (z_range) and the tile
// itself (lib/terrainlod/tile_codec: decode_tile, progressive tiles against their decoded
// parents), the nodata section of a version 2 archive (build --nodata hole: decoded,
// checked against the manifest, then every tile's base triangulation cut by it). Bytes
// that are no archive are decoded as one standalone .tlt tile, bytes starting "FTNM" as a
// nodata mask (its rule asked for triangles in and beyond the grid), and a JSON object as
// an extraction camera (parse_camera). Anything must end in a pyramid, a tile, a mask or a
// clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "pyramid_file.hpp"
#include "pyramid_view.hpp"
#include "terrainlod/nodata_mask.hpp"
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
        if (pyr.nodata()) {
          terrainlod::TileTriangulation tri = terrainlod::triangulate(pyr.tile(e.id), 0, pyr.geometry(e.id.level));
          terrainlod::cut_holes(*pyr.nodata(), tri);
        }
      }
      return 0;
    }
    if (bytes.size() >= 4 && bytes.substr(0, 4) == "FTNM") {
      const terrainlod::NodataMask m = terrainlod::decode_nodata_mask(bytes);
      const std::int64_t w = m.width, h = m.height;
      terrainlod::covers_nodata(m, {{{0, 0}, {w, 0}, {0, h}}});
      terrainlod::covers_nodata(m, {{{w - 1, h - 1}, {2 * w, h}, {w, 2 * h + 1}}});
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

// terrainlod decode: one tile for a neighbour mask -> a mesh (and its stored texture).

#include "commands.hpp"


#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "pyramid_view.hpp"

namespace fest::terrainlod_tool {

int run_decode(const DecodeArgs& args) {
  const terrainlod::TileId id = args.tile;
  if (args.mask < 0 || args.mask > 15) throw usage_error("--mask must be 0..15 (got {})", args.mask);
  const auto out = mesh_output(args.output, args.to);
  PyramidFile pyr = open_pyramid(args.pyramid);
  if (!pyr.has(id)) throw bad_input("pyramid has no tile {}/{}/{} ({})", id.level, id.x, id.y, pyr.name());
  const auto& t = pyr.tile(id);
  if ((static_cast<unsigned>(args.mask) & ~t.refinable) != 0)
    throw bad_input("tile {}/{}/{} has no finer neighbour on the sides of mask {} (refinable sides: {})", id.level, id.x, id.y,
                    args.mask, t.refinable);
  const std::string bytes = formats::write_mesh(
      world_mesh(pyr, {{id, terrainlod::triangulate(t, static_cast<unsigned>(args.mask), pyr.geometry(id.level))}}), out.format);
  std::string texture;
  if (!args.texture.empty()) texture = std::string(pyr.texture_bytes(id));
  formats::store_output(args.output, bytes, out.gzip);
  if (!texture.empty()) write_output(args.texture, texture);
  return 0;
}

}  // namespace fest::terrainlod_tool

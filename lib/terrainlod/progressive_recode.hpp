#pragma once
// Turning the builder's standalone tiles into progressive ones (docs/terrainlod.md §4). The
// builder works from the leaves up, so a tile's parent does not exist yet when the tile is
// coded; the writer goes root first and recodes each level against the level before it,
// a chunk of rows at a time, with only the parents of that chunk decoded. Recoding keeps
// each tile's strip order (tile_codec.hpp recode_tile), so it costs two decodes and one
// coding pass, no strip search.

#include <string>
#include <string_view>
#include <vector>

#include "terrainlod/tile_codec.hpp"

namespace fest::terrainlod {

struct CodedTile {
  TileId id;
  std::string_view bytes;
};

// Recodes every child progressively against its parent, which must be among `parents`
// (coded standalone: they are decoded alone). In parallel on `threads`; the result (in the
// children's order) does not depend on the thread count. `sizes`, if given, gets each
// result's sizes.
std::vector<std::string> recode_progressive(const std::vector<CodedTile>& children, const std::vector<CodedTile>& parents,
                                            int threads, std::vector<TileSizes>* sizes = nullptr);

}  // namespace fest::terrainlod

#include "terrainlod/progressive_recode.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::terrainlod {

std::vector<std::string> recode_progressive(const std::vector<CodedTile>& children, const std::vector<CodedTile>& parents,
                                            int threads, std::vector<TileSizes>* sizes) {
  std::vector<Tile> decoded(parents.size());
  parallel_for(parents.size(), threads, [&](std::size_t i) {
    if (tile_coding(parents[i].bytes) != TileCoding::standalone)
      throw runtime_failure("progressive recoding: parent {}/{}/{} is not standalone", parents[i].id.level, parents[i].id.x,
                            parents[i].id.y);
    decoded[i] = decode_tile(parents[i].bytes);
  });
  std::vector<std::size_t> order(parents.size());  // parents by id, for the lookup
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return parents[a].id < parents[b].id; });
  auto parent_of = [&](const TileId& child) -> const Tile* {
    const TileId want = parent_id(child);
    const auto it = std::lower_bound(order.begin(), order.end(), want,
                                     [&](std::size_t a, const TileId& id) { return parents[a].id < id; });
    if (it == order.end() || !(parents[*it].id == want))
      throw runtime_failure("progressive recoding: the parent of tile {}/{}/{} is missing", child.level, child.x, child.y);
    return &decoded[*it];
  };
  std::vector<std::string> out(children.size());
  if (sizes) sizes->assign(children.size(), TileSizes{});
  parallel_for(children.size(), threads, [&](std::size_t i) {
    const Tile* parent = children[i].id.level > 0 ? parent_of(children[i].id) : nullptr;
    out[i] = recode_tile(children[i].bytes, TileCoding::progressive, parent, sizes ? &(*sizes)[i] : nullptr);
  });
  return out;
}

}  // namespace fest::terrainlod

#pragma once
// The .tlp pyramid archive (man5/terrainlod-pyramid.5): "FTLP", version, the manifest
// JSON (length-prefixed), an index of tiles in transmission order, then the tile blobs.

#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "terrainlod/extract.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/tile_codec.hpp"

namespace fest::terrainlod_tool {

struct TileEntry {
  terrainlod::TileId id;
  std::uint64_t offset = 0;
  std::uint32_t length = 0;
};

// The archive up to the tile blobs (magic, version, manifest, index) for tiles of the
// given ids and lengths in that order; the blobs follow it in the same order.
std::string archive_head(const nlohmann::json& manifest, const std::vector<TileEntry>& tiles);

// Serialises the archive; `sizes` receives each tile's section sizes (same order).
std::string write_archive(const nlohmann::json& manifest, const terrainlod::Pyramid& pyramid,
                          std::vector<terrainlod::TileSizes>* sizes = nullptr);

class PyramidFile {
 public:
  // Parses and checks the container (magic, version, manifest, index bounds); tiles
  // are decoded on demand. `name` is for messages.
  PyramidFile(std::string bytes, std::string name);

  const nlohmann::json& manifest() const { return manifest_; }
  const std::vector<TileEntry>& index() const { return index_; }
  const terrainlod::PyramidLayout& layout() const { return layout_; }
  terrainlod::TileGeometry geometry(int level) const;
  bool has(const terrainlod::TileId& id) const { return where_.count(id) != 0; }
  const terrainlod::Tile& tile(const terrainlod::TileId& id);  // decoded once, cached
  std::string_view tile_bytes(const terrainlod::TileId& id) const;
  std::size_t bytes_touched() const { return touched_; }
  std::size_t tiles_decoded() const { return decoded_; }
  std::size_t tiles_cached() const { return cache_.size(); }
  // Drops decoded tiles not in `keep` (the tile cache of a camera path); returns how many.
  std::size_t keep_only(const std::set<terrainlod::TileId>& keep);
  std::size_t size() const { return bytes_.size(); }
  const std::string& name() const { return name_; }

 private:
  std::string bytes_;
  std::string name_;
  nlohmann::json manifest_;
  std::vector<TileEntry> index_;
  std::map<terrainlod::TileId, std::size_t> where_;
  std::map<terrainlod::TileId, terrainlod::Tile> cache_;
  terrainlod::PyramidLayout layout_;
  std::size_t touched_ = 0;
  std::size_t decoded_ = 0;
};

bool looks_like_archive(std::string_view bytes);

}  // namespace fest::terrainlod_tool

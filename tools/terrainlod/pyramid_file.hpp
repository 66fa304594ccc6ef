#pragma once
// The two pyramid containers (man5/terrainlod-pyramid.5):
//  * the .tlp archive (its bytes <-> types codec: lib/terrainlod/tlp_archive.hpp);
//  * the directory: pyramid.json (the manifest) + L/X/Y.tlt + L/X/Y.png (or .jpg).
// PyramidFile reads either; everything downstream sees the same tiles and textures.

#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "terrainlod/extract.hpp"
#include "terrainlod/nodata_mask.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/tlp_archive.hpp"

namespace fest::terrainlod_tool {

// One tile of the archive's index (lib/terrainlod/tlp_archive.hpp holds the codec).
using TileEntry = terrainlod::TlpEntry;

// Writes the directory container tile by tile into a temporary sibling that commit()
// renames into place; destroyed uncommitted, it removes the partial directory. An
// existing directory is replaced only if it is a pyramid (has pyramid.json).
// `texture_extension` is "png" or "jpg".
class DirectoryPyramidWriter {
 public:
  DirectoryPyramidWriter(const std::string& dir, const nlohmann::json& manifest, std::string texture_extension);
  ~DirectoryPyramidWriter();
  DirectoryPyramidWriter(const DirectoryPyramidWriter&) = delete;
  DirectoryPyramidWriter& operator=(const DirectoryPyramidWriter&) = delete;
  // `texture` empty: the tile has none.
  void add(const terrainlod::TileId& id, std::string_view tile, std::string_view texture);
  // build --nodata hole: the nodata mask's bytes (nodata.bin).
  void add_nodata(std::string_view section);
  void commit();

 private:
  std::filesystem::path target_, tmp_;
  std::string texture_extension_;
  bool replace_ = false, committed_ = false;
};

class PyramidFile {
 public:
  // Parses and checks an archive (magic, version, manifest, index bounds); tiles are
  // decoded on demand. `name` is for messages.
  PyramidFile(std::string bytes, std::string name);
  // An archive file, standard input ("-") or a pyramid directory.
  static PyramidFile open(const std::string& path);

  const nlohmann::json& manifest() const { return manifest_; }
  const std::vector<TileEntry>& index() const { return index_; }
  const terrainlod::PyramidLayout& layout() const { return layout_; }
  terrainlod::TileGeometry geometry(int level) const;
  bool has(const terrainlod::TileId& id) const { return where_.count(id) != 0; }
  // build --nodata hole: the nodata mask (no triangle is drawn over a nodata sample); null
  // for a filled pyramid.
  const terrainlod::NodataMask* nodata() const { return holes_ ? &nodata_ : nullptr; }
  // Decoded once, cached; a progressive tile decodes (and caches) its parent chain first.
  const terrainlod::Tile& tile(const terrainlod::TileId& id);
  // The decoded parent a tile's coding refers to, or null for a standalone tile.
  const terrainlod::Tile* parent_of(const terrainlod::TileId& id);
  // A tile's height range from its header alone (read once, cached; selection examines
  // many tiles it never draws, so it must not decode them).
  std::array<float, 2> z_range(const terrainlod::TileId& id);
  std::string_view tile_bytes(const terrainlod::TileId& id) const;
  // Texture tiles: whether the pyramid has them, their file extension ("png" or "jpg"),
  // and one tile's encoded image (counted in bytes_touched).
  bool textured() const { return textured_; }
  const std::string& texture_extension() const { return texture_extension_; }
  std::string_view texture_bytes(const terrainlod::TileId& id);
  std::size_t bytes_touched() const { return touched_; }
  std::size_t tiles_decoded() const { return decoded_; }
  std::size_t tiles_cached() const { return cache_.size(); }
  // Drops decoded tiles not in `keep` or ancestors of a tile in it (the tile cache of a
  // camera path; progressive tiles need their ancestors to decode); returns how many.
  std::size_t keep_only(const std::set<terrainlod::TileId>& keep);
  std::size_t size() const { return total_bytes_; }
  const std::string& name() const { return name_; }
  bool is_directory() const { return !dir_.empty(); }

 private:
  PyramidFile() = default;
  void parse_manifest(std::string_view text);
  // The manifest's "nodata" ("fill" when absent) against the section's bytes (empty: none).
  void parse_nodata(std::string_view section);
  std::string tile_path(const terrainlod::TileId& id, const std::string& extension) const;

  std::string bytes_;  // the archive
  std::string dir_;    // or the directory
  std::string name_;
  nlohmann::json manifest_;
  std::vector<TileEntry> index_;
  std::map<terrainlod::TileId, std::size_t> where_;
  std::map<terrainlod::TileId, terrainlod::Tile> cache_;
  std::map<terrainlod::TileId, std::array<float, 2>> z_ranges_;
  mutable std::map<terrainlod::TileId, std::string> files_, texture_files_;  // directory blobs read so far
  terrainlod::PyramidLayout layout_;
  bool textured_ = false;
  bool holes_ = false;
  terrainlod::NodataMask nodata_;
  std::string texture_extension_;
  std::size_t total_bytes_ = 0;
  std::size_t touched_ = 0;
  std::size_t decoded_ = 0;
};

}  // namespace fest::terrainlod_tool

#pragma once
// The .tlp pyramid archive as bytes <-> types (man5/terrainlod-pyramid.5): "FTLP", a
// version byte, the manifest JSON (length-prefixed), an index of tiles in transmission
// order (level, x, y, geometry offset and length, texture offset and length), then the
// blobs. No file access here: the caller holds the archive's bytes. Errors are bad_input
// in the archive's terms; the caller adds the file's name.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

struct TlpEntry {
  TileId id;
  std::uint64_t offset = 0;
  std::uint32_t length = 0;
  std::uint64_t texture_offset = 0;  // 0 with length 0 = no texture
  std::uint32_t texture_length = 0;
};

bool looks_like_tlp(std::string_view bytes);

// The archive up to the tile blobs for tiles of the given ids, geometry lengths and
// texture lengths in that order (offsets are computed); each tile's geometry blob, then
// its texture, follow in the same order, so a reader streaming in transmission order
// gets both of a tile together.
std::string encode_tlp_head(std::string_view manifest_json, const std::vector<TlpEntry>& tiles);

// The manifest's text and where the index starts. Checks magic, version and that the
// manifest is complete.
struct TlpHead {
  std::string_view manifest;
  std::size_t index_at = 0;
};
TlpHead decode_tlp_head(std::string_view bytes);

// The index (after decode_tlp_head), its offsets as stored: the caller checks them
// against the pyramid it describes and the archive's size.
std::vector<TlpEntry> decode_tlp_index(std::string_view bytes, std::size_t index_at);

}  // namespace fest::terrainlod

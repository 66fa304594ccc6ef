#pragma once
// The .tlp pyramid archive as bytes <-> types (man5/terrainlod-pyramid.5): "FTLP", a
// version byte, the manifest JSON (length-prefixed), an index of tiles in transmission
// order (level, x, y, geometry offset and length, texture offset and length), in version
// 2 the nodata section (length-prefixed: the mask of build --nodata hole,
// nodata_mask.hpp), then the blobs. Version 1 (no section) is written whenever there is
// no mask, so filled pyramids keep their bytes. No file access here: the caller holds the archive's bytes. Errors are bad_input
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
// A non-empty `nodata` section makes a version 2 archive.
std::string encode_tlp_head(std::string_view manifest_json, const std::vector<TlpEntry>& tiles, std::string_view nodata = {});

// The manifest's text and where the index starts. Checks magic, version and that the
// manifest is complete.
struct TlpHead {
  std::string_view manifest;
  std::size_t index_at = 0;
  int version = 1;
};
TlpHead decode_tlp_head(std::string_view bytes);

// The index (after decode_tlp_head), its offsets as stored: the caller checks them
// against the pyramid it describes and the archive's size.
std::vector<TlpEntry> decode_tlp_index(std::string_view bytes, std::size_t index_at);

// The nodata section's bytes (version 2), empty for version 1; checked to lie inside the
// archive, not decoded (decode_nodata_mask does that).
std::string_view decode_tlp_nodata(std::string_view bytes, const TlpHead& head);

}  // namespace fest::terrainlod

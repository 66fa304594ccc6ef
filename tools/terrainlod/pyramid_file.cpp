#include "pyramid_file.hpp"

#include "core/error.hpp"

namespace fest::terrainlod_tool {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'L', 'P'};
constexpr std::uint8_t kVersion = 1;
constexpr std::size_t kEntryBytes = 1 + 4 + 4 + 8 + 4 + 8 + 4;

template <typename T>
void put_le(std::string& s, T v) {
  for (std::size_t b = 0; b < sizeof(T); ++b) s.push_back(static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * b)) & 0xff));
}
template <typename T>
T get_le(std::string_view s, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < sizeof(T); ++b) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(s[at + b])) << (8 * b);
  return static_cast<T>(v);
}

}  // namespace

bool looks_like_archive(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == std::string_view(kMagic, 4); }

std::string archive_head(const nlohmann::json& manifest, const std::vector<TileEntry>& tiles) {
  const std::string m = manifest.dump();
  std::string out(kMagic, 4);
  put_le<std::uint8_t>(out, kVersion);
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(m.size()));
  out += m;
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(tiles.size()));
  std::uint64_t offset = out.size() + kEntryBytes * tiles.size();
  for (const auto& t : tiles) {
    put_le<std::uint8_t>(out, static_cast<std::uint8_t>(t.id.level));
    put_le<std::uint32_t>(out, static_cast<std::uint32_t>(t.id.x));
    put_le<std::uint32_t>(out, static_cast<std::uint32_t>(t.id.y));
    put_le<std::uint64_t>(out, offset);
    put_le<std::uint32_t>(out, t.length);
    put_le<std::uint64_t>(out, 0);  // texture offset: no textures in this version
    put_le<std::uint32_t>(out, 0);
    offset += t.length;
  }
  return out;
}

std::string write_archive(const nlohmann::json& manifest, const terrainlod::Pyramid& pyramid,
                          std::vector<terrainlod::TileSizes>* sizes) {
  std::vector<std::string> blobs;
  std::vector<TileEntry> entries;
  for (const auto& t : pyramid.tiles) {
    terrainlod::TileSizes s;
    blobs.push_back(terrainlod::encode_tile(t, &s));
    entries.push_back({t.id, 0, static_cast<std::uint32_t>(blobs.back().size())});
    if (sizes) sizes->push_back(s);
  }
  std::string out = archive_head(manifest, entries);
  for (const auto& b : blobs) out += b;
  return out;
}

PyramidFile::PyramidFile(std::string bytes, std::string name) : bytes_(std::move(bytes)), name_(std::move(name)) {
  const std::string_view s(bytes_);
  if (!looks_like_archive(s)) throw bad_input("not a terrainlod pyramid (bad magic) ({})", name_);
  if (s.size() < 9) throw bad_input("pyramid is truncated: {} bytes ({})", s.size(), name_);
  if (get_le<std::uint8_t>(s, 4) != kVersion)
    throw bad_input("pyramid version {} is not supported (this is version {}) ({})", get_le<std::uint8_t>(s, 4), kVersion, name_);
  const std::size_t mlen = get_le<std::uint32_t>(s, 5);
  if (s.size() < 9 + mlen + 4) throw bad_input("pyramid is truncated in its manifest ({})", name_);
  try {
    manifest_ = nlohmann::json::parse(s.substr(9, mlen));
    layout_.levels = manifest_.at("levels").get<int>();
    layout_.texels = manifest_.at("texels").get<int>();
    layout_.origin_x = manifest_.at("origin").at(0).get<double>();
    layout_.origin_y = manifest_.at("origin").at(1).get<double>();
    layout_.dx = manifest_.at("cell_size").at(0).get<double>();
    layout_.dy = manifest_.at("cell_size").at(1).get<double>();
    for (const auto& lv : manifest_.at("level")) {
      layout_.tiles_x.push_back(lv.at("tiles_x").get<int>());
      layout_.tiles_y.push_back(lv.at("tiles_y").get<int>());
      layout_.cells.push_back(lv.at("cells").get<int>());
    }
    manifest_.at("z_quantum").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("pyramid manifest is malformed: {} ({})", e.what(), name_);
  }
  if (layout_.levels < 0 || layout_.levels > 30 || static_cast<int>(layout_.cells.size()) != layout_.levels + 1 ||
      layout_.texels <= 0)
    throw bad_input("pyramid manifest is inconsistent ({})", name_);
  for (int c : layout_.cells)
    if (c <= 0) throw bad_input("pyramid manifest is inconsistent ({})", name_);
  std::size_t at = 9 + mlen;
  const std::size_t count = get_le<std::uint32_t>(s, at);
  at += 4;
  if (s.size() < at + count * kEntryBytes) throw bad_input("pyramid is truncated in its tile index ({})", name_);
  for (std::size_t i = 0; i < count; ++i, at += kEntryBytes) {
    TileEntry e;
    e.id = {get_le<std::uint8_t>(s, at), static_cast<int>(get_le<std::uint32_t>(s, at + 1)),
            static_cast<int>(get_le<std::uint32_t>(s, at + 5))};
    e.offset = get_le<std::uint64_t>(s, at + 9);
    e.length = get_le<std::uint32_t>(s, at + 17);
    if (!layout_.exists(e.id)) throw bad_input("pyramid index names tile {}/{}/{} outside the pyramid ({})", e.id.level, e.id.x, e.id.y, name_);
    if (e.offset > s.size() || s.size() - e.offset < e.length)
      throw bad_input("tile {}/{}/{} is truncated: {} of {} bytes ({})", e.id.level, e.id.x, e.id.y,
                      e.offset > s.size() ? 0 : s.size() - e.offset, e.length, name_);
    where_[e.id] = index_.size();
    index_.push_back(e);
  }
}

std::size_t PyramidFile::keep_only(const std::set<terrainlod::TileId>& keep) {
  std::size_t evicted = 0;
  for (auto it = cache_.begin(); it != cache_.end();) {
    if (keep.count(it->first)) {
      ++it;
    } else {
      it = cache_.erase(it);
      ++evicted;
    }
  }
  return evicted;
}

terrainlod::TileGeometry PyramidFile::geometry(int level) const {
  return {layout_.cells[static_cast<std::size_t>(level)], manifest_.at("z_quantum").get<double>()};
}

std::string_view PyramidFile::tile_bytes(const terrainlod::TileId& id) const {
  const auto it = where_.find(id);
  if (it == where_.end()) throw bad_input("pyramid has no tile {}/{}/{} ({})", id.level, id.x, id.y, name_);
  const TileEntry& e = index_[it->second];
  return std::string_view(bytes_).substr(e.offset, e.length);
}

const terrainlod::Tile& PyramidFile::tile(const terrainlod::TileId& id) {
  auto it = cache_.find(id);
  if (it != cache_.end()) return it->second;
  const std::string_view b = tile_bytes(id);
  touched_ += b.size();
  ++decoded_;
  terrainlod::Tile t;
  try {
    t = terrainlod::decode_tile(b);
  } catch (const Error& e) {
    throw bad_input("{} ({})", e.what(), name_);
  }
  if (!(t.id == id)) throw bad_input("pyramid index and tile header disagree on tile {}/{}/{} ({})", id.level, id.x, id.y, name_);
  return cache_.emplace(id, std::move(t)).first->second;
}

}  // namespace fest::terrainlod_tool

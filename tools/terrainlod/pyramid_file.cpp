#include "pyramid_file.hpp"
#include "core/json_value.hpp"
#include "core/quote.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/error.hpp"
#include "core/file_io.hpp"

namespace fest::terrainlod_tool {
namespace fs = std::filesystem;
namespace {

// The archive codec's errors name no file; the tool adds which one.
template <typename F>
auto naming(const std::string& name, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    throw Error(e.status(), fmt::format("{} ({})", e.what(), name));
  }
}

std::string relative_tile_path(const terrainlod::TileId& id, const std::string& extension) {
  return std::to_string(id.level) + "/" + std::to_string(id.x) + "/" + std::to_string(id.y) + "." + extension;
}

void write_file(const fs::path& p, std::string_view bytes) {
  std::ofstream out(p, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw io_error("cannot write {}", p.string());
}

}  // namespace

DirectoryPyramidWriter::DirectoryPyramidWriter(const std::string& dir, const nlohmann::json& manifest, std::string texture_extension)
    : texture_extension_(std::move(texture_extension)) {
  const fs::path norm = fs::path(dir).lexically_normal();
  target_ = norm.filename().empty() ? norm.parent_path() : norm;
  std::error_code ec;
  replace_ = fs::exists(target_, ec);
  if (replace_ && !(fs::is_directory(target_, ec) && (fs::is_empty(target_, ec) || fs::exists(target_ / "pyramid.json", ec))))
    throw io_error("{} exists and is not a pyramid directory; not replacing it", target_.string());
  tmp_ = target_.string() + ".part-" + std::to_string(::getpid());
  fs::remove_all(tmp_, ec);
  try {
    fs::create_directories(tmp_);
    write_file(tmp_ / "pyramid.json", manifest.dump(2) + "\n");
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(tmp_, ec);
    throw io_error("cannot write the pyramid directory {}: {}", target_.string(), e.code().message());
  } catch (...) {
    fs::remove_all(tmp_, ec);
    throw;
  }
}

DirectoryPyramidWriter::~DirectoryPyramidWriter() {
  std::error_code ec;
  if (!committed_) fs::remove_all(tmp_, ec);
}

void DirectoryPyramidWriter::add(const terrainlod::TileId& id, std::string_view tile, std::string_view texture) {
  try {
    const fs::path tlt = tmp_ / relative_tile_path(id, "tlt");
    fs::create_directories(tlt.parent_path());
    write_file(tlt, tile);
    if (!texture.empty()) write_file(tmp_ / relative_tile_path(id, texture_extension_), texture);
  } catch (const fs::filesystem_error& e) {
    throw io_error("cannot write the pyramid directory {}: {}", target_.string(), e.code().message());
  }
}

void DirectoryPyramidWriter::add_nodata(std::string_view section) {
  try {
    write_file(tmp_ / "nodata.bin", section);
  } catch (const fs::filesystem_error& e) {
    throw io_error("cannot write the pyramid directory {}: {}", target_.string(), e.code().message());
  }
}

void DirectoryPyramidWriter::commit() {
  std::error_code ec;
  const fs::path old = target_.string() + ".old-" + std::to_string(::getpid());
  try {
    if (replace_) fs::rename(target_, old);
  } catch (const fs::filesystem_error& e) {
    throw io_error("cannot replace the pyramid directory {}: {}", target_.string(), e.code().message());
  }
  fs::rename(tmp_, target_, ec);
  if (ec) {
    std::error_code ignored;
    if (replace_) fs::rename(old, target_, ignored);
    throw io_error("cannot rename {} to {}: {}", tmp_.string(), target_.string(), ec.message());
  }
  committed_ = true;
  if (replace_) fs::remove_all(old, ec);
}

void PyramidFile::parse_manifest(std::string_view text) {
  try {
    manifest_ = nlohmann::json::parse(text);
    layout_.levels = json_integer<int>(manifest_.at("levels"));
    layout_.texels = json_integer<int>(manifest_.at("texels"));
    layout_.origin_x = manifest_.at("origin").at(0).get<double>();
    layout_.origin_y = manifest_.at("origin").at(1).get<double>();
    layout_.dx = manifest_.at("cell_size").at(0).get<double>();
    layout_.dy = manifest_.at("cell_size").at(1).get<double>();
    for (const auto& lv : manifest_.at("level")) {
      layout_.tiles_x.push_back(json_integer<int>(lv.at("tiles_x")));
      layout_.tiles_y.push_back(json_integer<int>(lv.at("tiles_y")));
      layout_.cells.push_back(json_integer<int>(lv.at("cells")));
      // Read by stats and verify: checked here, so that a damaged manifest is refused on
      // opening in fest's words, not later by the JSON library.
      lv.at("eps").get<double>();
      json_integer<int>(lv.at("lattice_bits"));
    }
    // Words stats and verify read later: checked here for the same reason.
    for (const char* word : {"diagonal", "reference", "coding"}) json_string_or(manifest_, word, "");
    manifest_.at("z_quantum").get<double>();
    manifest_.at("width").get<double>();
    manifest_.at("height").get<double>();
    const auto tex = manifest_.find("texture");
    if (tex != manifest_.end() && !tex->is_null()) {
      const std::string format = tex->at("format").get<std::string>();
      if (format != "png" && format != "jpeg") throw bad_input("pyramid textures are '{}', not png or jpeg ({})", quoted_bytes(format), name_);
      textured_ = true;
      texture_extension_ = format == "png" ? "png" : "jpg";
    }
  } catch (const nlohmann::json::parse_error& e) {
    throw bad_input("pyramid manifest is malformed: {} ({})", json_failure_words(e.what(), e.byte, text), name_);
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("pyramid manifest is malformed: {} ({})", json_failure_words(e.what(), 0, text), name_);
  }
  if (layout_.levels < 0 || layout_.levels > 30 || static_cast<int>(layout_.cells.size()) != layout_.levels + 1 ||
      layout_.texels <= 0)
    throw bad_input("pyramid manifest is inconsistent ({})", name_);
  for (int c : layout_.cells)
    if (c <= 0) throw bad_input("pyramid manifest is inconsistent ({})", name_);
  for (std::size_t l = 0; l < layout_.cells.size(); ++l)
    if (layout_.tiles_x[l] <= 0 || layout_.tiles_y[l] <= 0 || layout_.tiles_x[l] > (1 << l) || layout_.tiles_y[l] > (1 << l))
      throw bad_input("pyramid manifest is inconsistent ({})", name_);
}

void PyramidFile::parse_nodata(std::string_view section) {
  std::string mode = "fill";
  try {
    const auto it = manifest_.find("nodata");
    if (it != manifest_.end()) mode = it->get<std::string>();
  } catch (const nlohmann::json::exception&) {
    throw bad_input("pyramid manifest's nodata is not a word ({})", name_);
  }
  if (mode != "fill" && mode != "hole") throw bad_input("pyramid manifest's nodata is '{}', not fill or hole ({})", quoted_bytes(mode), name_);
  if (mode == "fill") {
    if (!section.empty()) throw bad_input("pyramid has a nodata mask but its manifest says nodata fill ({})", name_);
    return;
  }
  if (section.empty()) throw bad_input("pyramid manifest says nodata hole but the pyramid has no nodata mask ({})", name_);
  nodata_ = naming(name_, [&] { return terrainlod::decode_nodata_mask(section); });
  if (nodata_.width != json_integer_or<std::int64_t>(manifest_, "width", -1) || nodata_.height != json_integer_or<std::int64_t>(manifest_, "height", -1))
    throw bad_input("pyramid's nodata mask is {} x {} samples, its DEM {} x {} ({})", nodata_.width, nodata_.height,
                    json_integer_or<std::int64_t>(manifest_, "width", -1), json_integer_or<std::int64_t>(manifest_, "height", -1), name_);
  holes_ = true;
}

PyramidFile::PyramidFile(std::string bytes, std::string name) : bytes_(std::move(bytes)), name_(std::move(name)) {
  const std::string_view s(bytes_);
  total_bytes_ = s.size();
  const terrainlod::TlpHead head = naming(name_, [&] { return terrainlod::decode_tlp_head(s); });
  parse_manifest(head.manifest);
  parse_nodata(naming(name_, [&] { return terrainlod::decode_tlp_nodata(s, head); }));
  for (const TileEntry& e : naming(name_, [&] { return terrainlod::decode_tlp_index(s, head.index_at); })) {
    if (!layout_.exists(e.id)) throw bad_input("pyramid index names tile {}/{}/{} outside the pyramid ({})", e.id.level, e.id.x, e.id.y, name_);
    if (e.offset > s.size() || s.size() - e.offset < e.length)
      throw bad_input("tile {}/{}/{} is truncated: {} of {} bytes ({})", e.id.level, e.id.x, e.id.y,
                      e.offset > s.size() ? 0 : s.size() - e.offset, e.length, name_);
    if (textured_ && e.texture_length == 0)
      throw bad_input("pyramid has textures but none for tile {}/{}/{} ({})", e.id.level, e.id.x, e.id.y, name_);
    if (e.texture_offset > s.size() || s.size() - e.texture_offset < e.texture_length)
      throw bad_input("texture of tile {}/{}/{} is truncated: {} of {} bytes ({})", e.id.level, e.id.x, e.id.y,
                      e.texture_offset > s.size() ? 0 : s.size() - e.texture_offset, e.texture_length, name_);
    where_[e.id] = index_.size();
    index_.push_back(e);
  }
}

PyramidFile PyramidFile::open(const std::string& path) {
  std::error_code ec;
  if (is_stdio(path) || !fs::is_directory(path, ec)) return PyramidFile(read_input(path), is_stdio(path) ? "-" : path);
  PyramidFile p;
  p.dir_ = path;
  p.name_ = path;
  const fs::path manifest = fs::path(path) / "pyramid.json";
  if (!fs::exists(manifest, ec)) throw bad_input("not a terrainlod pyramid: directory without pyramid.json ({})", path);
  const std::string text = read_input(manifest.string());
  p.total_bytes_ = text.size();
  p.parse_manifest(text);
  const fs::path mask = fs::path(path) / "nodata.bin";
  std::string section;
  if (fs::exists(mask, ec)) {
    section = read_input(mask.string());
    p.total_bytes_ += section.size();
  }
  p.parse_nodata(section);
  // Every tile of the layout, in transmission order (level, then rows from the south, then
  // columns), must be there with its texture when the manifest says there are textures.
  const auto& L = p.layout_;
  for (int l = 0; l <= L.levels; ++l)
    for (int y = 0; y < L.tiles_y[static_cast<std::size_t>(l)]; ++y)
      for (int x = 0; x < L.tiles_x[static_cast<std::size_t>(l)]; ++x) {
        TileEntry e;
        e.id = {l, x, y};
        const std::string tlt = p.tile_path(e.id, "tlt");
        const auto n = fs::file_size(tlt, ec);
        if (ec) throw bad_input("pyramid directory lacks tile {}/{}/{} ({})", l, x, y, tlt);
        e.length = static_cast<std::uint32_t>(n);
        if (p.textured_) {
          const std::string tex = p.tile_path(e.id, p.texture_extension_);
          const auto t = fs::file_size(tex, ec);
          if (ec) throw bad_input("pyramid directory lacks the texture of tile {}/{}/{} ({})", l, x, y, tex);
          e.texture_length = static_cast<std::uint32_t>(t);
        }
        p.total_bytes_ += e.length + e.texture_length;
        p.where_[e.id] = p.index_.size();
        p.index_.push_back(e);
      }
  return p;
}

std::string PyramidFile::tile_path(const terrainlod::TileId& id, const std::string& extension) const {
  return (fs::path(dir_) / relative_tile_path(id, extension)).string();
}

std::size_t PyramidFile::keep_only(const std::set<terrainlod::TileId>& keep) {
  // The ancestors of kept tiles stay too: a progressive tile decoded later (a child of a
  // kept one, or its sibling) needs them, and they are few (one chain per tile).
  std::set<terrainlod::TileId> keep_all = keep;
  for (const auto& id : keep)
    for (terrainlod::TileId a = id; a.level > 0;) {
      a = terrainlod::parent_id(a);
      if (!keep_all.insert(a).second) break;  // its ancestors are in already
    }
  std::size_t evicted = 0;
  for (auto it = z_ranges_.begin(); it != z_ranges_.end();) it = keep_all.count(it->first) ? std::next(it) : z_ranges_.erase(it);
  for (auto it = cache_.begin(); it != cache_.end();) {
    if (keep_all.count(it->first)) {
      ++it;
    } else {
      files_.erase(it->first);
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
  if (!is_directory()) return std::string_view(bytes_).substr(e.offset, e.length);
  auto f = files_.find(id);
  if (f == files_.end()) f = files_.emplace(id, read_input(tile_path(id, "tlt"))).first;
  return f->second;
}

std::string_view PyramidFile::texture_bytes(const terrainlod::TileId& id) {
  if (!textured_) throw bad_input("pyramid has no textures ({})", name_);
  const auto it = where_.find(id);
  if (it == where_.end()) throw bad_input("pyramid has no tile {}/{}/{} ({})", id.level, id.x, id.y, name_);
  const TileEntry& e = index_[it->second];
  std::string_view b;
  if (!is_directory()) {
    b = std::string_view(bytes_).substr(e.texture_offset, e.texture_length);
  } else {
    auto f = texture_files_.find(id);
    if (f == texture_files_.end()) f = texture_files_.emplace(id, read_input(tile_path(id, texture_extension_))).first;
    b = f->second;
  }
  touched_ += b.size();
  return b;
}

const terrainlod::Tile& PyramidFile::tile(const terrainlod::TileId& id) {
  auto it = cache_.find(id);
  if (it != cache_.end()) return it->second;
  const std::string_view b = tile_bytes(id);
  // A progressive tile is coded against its decoded parent (docs/terrainlod.md §4): decode the chain
  // up to the nearest cached or standalone ancestor first (each one cached; std::map
  // nodes stay put while others are inserted).
  const terrainlod::Tile* parent = parent_of(id);
  touched_ += z_ranges_.count(id) ? b.size() - terrainlod::kTileHeaderBytes : b.size();  // the header was counted
  ++decoded_;
  terrainlod::Tile t;
  try {
    t = terrainlod::decode_tile(b, parent);
  } catch (const Error& e) {
    throw bad_input("{} ({})", e.what(), name_);
  }
  if (!(t.id == id)) throw bad_input("pyramid index and tile header disagree on tile {}/{}/{} ({})", id.level, id.x, id.y, name_);
  return cache_.emplace(id, std::move(t)).first->second;
}

std::array<float, 2> PyramidFile::z_range(const terrainlod::TileId& id) {
  if (const auto c = cache_.find(id); c != cache_.end()) return {c->second.z_min, c->second.z_max};
  if (const auto z = z_ranges_.find(id); z != z_ranges_.end()) return z->second;
  const std::string_view b = tile_bytes(id);
  terrainlod::TileHeader h;
  try {
    h = terrainlod::read_tile_header(b);
  } catch (const Error& e) {
    throw bad_input("{} ({})", e.what(), name_);
  }
  if (!(h.id == id)) throw bad_input("pyramid index and tile header disagree on tile {}/{}/{} ({})", id.level, id.x, id.y, name_);
  touched_ += terrainlod::kTileHeaderBytes;
  return z_ranges_.emplace(id, std::array<float, 2>{h.z_min, h.z_max}).first->second;
}

const terrainlod::Tile* PyramidFile::parent_of(const terrainlod::TileId& id) {
  if (id.level == 0 || terrainlod::tile_coding(tile_bytes(id)) != terrainlod::TileCoding::progressive) return nullptr;
  const terrainlod::TileId up = terrainlod::parent_id(id);
  if (!has(up))
    throw bad_input("tile {}/{}/{} is coded relative to its parent {}/{}/{}, which the pyramid lacks ({})", id.level, id.x, id.y,
                    up.level, up.x, up.y, name_);
  return &tile(up);
}

}  // namespace fest::terrainlod_tool

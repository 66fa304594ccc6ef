// terrainlod build: a DEM (and a texture) -> the tile pyramid, .tlp archive or directory, streamed
// level by level through spill files so that memory holds one chunk of tiles.

#include "commands.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/parallel_for.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/resources.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "dem_input.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "pyramid_file.hpp"
#include "pyramid_options.hpp"
#include "terrainlod/nodata_mask.hpp"
#include "terrainlod/progressive_recode.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/texture_pyramid.hpp"

namespace fest::terrainlod_tool {
namespace {

Image read_texture(const std::string& path) {
  const std::string bytes = read_input(path);
  const std::string where = is_stdio(path) ? "-" : path;
  try {
    const formats::Format f = formats::detect_format(bytes, where);
    if (formats::kind_of(f) != formats::Kind::image) throw bad_input("texture is not an image but {}", formats::format_name(f));
    Image img = formats::read_image(bytes, f);
    img.pixels = terrainlod::texture_pixels(img.pixels);
    return img;
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    const std::string what = e.what();
    throw bad_input("{}", what.find(where) == std::string::npos ? fmt::format("{} ({})", what, where) : what);
  }
}

// A prefiltered texture pyramid PREFIX_<k>.png (k = 0 full size, each level about half the
// previous), as `resample mip build` writes it. Level files are read while they exist.
std::vector<Image> read_texture_mip(const std::string& prefix) {
  std::vector<Image> mips;
  std::error_code ec;
  for (int k = 0;; ++k) {
    const std::string png = prefix + "_" + std::to_string(k) + ".png", exr = prefix + "_" + std::to_string(k) + ".exr";
    if (std::filesystem::exists(png, ec)) {
      mips.push_back(read_texture(png));
    } else if (std::filesystem::exists(exr, ec)) {
      throw bad_input("texture pyramid level {} is floating point; texture tiles are 8-bit: build it from an 8 or 16-bit image ({})", k, exr);
    } else {
      break;
    }
  }
  if (mips.empty()) throw io_error("no texture pyramid level {}_0.png", prefix);
  for (std::size_t k = 1; k < mips.size(); ++k) {
    const cv::Mat& a = mips[k - 1].pixels;
    const cv::Mat& b = mips[k].pixels;
    if (std::abs(b.cols - a.cols / 2) > 1 || std::abs(b.rows - a.rows / 2) > 1 || b.channels() != a.channels())
      throw bad_input("texture pyramid level {} is {} x {} with {} channels after {} x {} with {}; each level must halve the previous ({}_{}.png)",
                      k, b.cols, b.rows, b.channels(), a.cols, a.rows, a.channels(), prefix, k);
  }
  return mips;
}

// The canvas of one level from a prefiltered pyramid: its coarsest image that still has a
// pixel per texel there (the finest, where none has), resampled like a single image with
// the level's tiles as leaves.
cv::Mat mip_canvas(const std::vector<Image>& mips, int level, const terrainlod::Pyramid& pyr, int tile, int texels, const LoadedDem& dem) {
  const int cells = tile << (pyr.levels - level);
  std::size_t k = 0;
  while (k + 1 < mips.size() &&
         static_cast<double>(mips[k + 1].pixels.cols) / (dem.grid.width - 1) * cells / texels >= 1.0 &&
         static_cast<double>(mips[k + 1].pixels.rows) / (dem.grid.height - 1) * cells / texels >= 1.0)
    ++k;
  const cv::Mat& img = mips[k].pixels;
  terrainlod::TextureLayout lay{level, cells, texels, dem.grid.width, dem.grid.height};
  return terrainlod::leaf_canvas(img, terrainlod::place_image(img.cols, img.rows, dem.grid.width, dem.grid.height), lay);
}

// Every tile's texture, encoded, in the order of `tiles`. The canvases come from one
// image (the leaf canvas, box-filtered per level) or from a prefiltered pyramid (`mips`).
std::vector<std::string> texture_tiles(const terrainlod::Pyramid& pyr, const std::vector<TileEntry>& tiles, const cv::Mat& pixels, terrainlod::ImagePlacement placement,
                                       const std::optional<terrainlod::ImageFrame>& georeferenced, const BuildArgs& args,
                                       int texels, const LoadedDem& dem, const std::vector<Image>& mips) {
  terrainlod::TextureLayout lay;
  lay.levels = pyr.levels;
  lay.tile = args.tile;
  lay.texels = texels;
  lay.width = dem.grid.width;
  lay.height = dem.grid.height;
  formats::ImageWriteOptions opt;
  const formats::Format format = args.texture_format == TextureFormat::jpeg ? formats::Format::jpeg : formats::Format::png;
  if (format == formats::Format::jpeg) opt.jpeg_quality = args.texture_quality;
  std::map<terrainlod::TileId, std::size_t> at;
  for (std::size_t i = 0; i < tiles.size(); ++i) at[tiles[i].id] = i;
  std::vector<std::string> out(tiles.size());
  cv::Mat canvas = !mips.empty()     ? cv::Mat()
                   : georeferenced ? terrainlod::leaf_canvas(pixels, *georeferenced, lay)
                                   : terrainlod::leaf_canvas(pixels, placement, lay);
  for (int l = pyr.levels; l >= 0; --l) {
    if (!mips.empty()) canvas = mip_canvas(mips, l, pyr, args.tile, texels, dem);
    else if (l < pyr.levels) canvas = terrainlod::halve_canvas(canvas);
    const auto& lv = pyr.level[static_cast<std::size_t>(l)];
    std::vector<std::pair<terrainlod::TileId, std::size_t>> jobs;
    for (int y = 0; y < lv.tiles_y; ++y)
      for (int x = 0; x < lv.tiles_x; ++x) {
        const auto it = at.find({l, x, y});
        if (it != at.end()) jobs.push_back({it->first, it->second});
      }
    // Encoding is independent per tile: spread it over the build's threads.
    parallel_for(jobs.size(), resolve_threads(args.threads), [&](std::size_t j) {
      Image tile;
      tile.pixels = terrainlod::tile_texture(canvas, l, jobs[j].first.x, jobs[j].first.y, texels);
      out[jobs[j].second] = formats::write_image(tile, format, opt);
    });
  }
  return out;
}

// The build's parameters from its flags, with the checks that need no input (usage
// errors before anything is read).
terrainlod::BuildParams build_params(const BuildArgs& args) {
  terrainlod::BuildParams params;
  params.pyramid.tile = args.tile;
  params.pyramid.texels = args.texels;
  params.pyramid.error_fraction = args.error_fraction;
  check_tile_options(args.tile, args.texels, args.error_fraction);  // usage errors before reading
  params.height_quantum = args.height_quantum;
  params.leaf_error = args.leaf_error;
  params.reference = args.reference;
  params.diagonal = args.dem.diagonal;
  params.start = args.start;
  params.threads = resolve_threads(args.threads);
  if (args.z_quantum < 0 || !std::isfinite(args.z_quantum)) throw usage_error("--z-quantum must be positive (got {})", args.z_quantum);
  return params;
}

// The texture of the tiles: one image (--texture) or a prefiltered pyramid (--texture-mip,
// its level 0 as the image), and where it lies on the DEM.
struct TextureSource {
  std::optional<Image> image;
  std::vector<Image> mips;
  std::optional<terrainlod::ImagePlacement> placement;
  std::optional<terrainlod::ImageFrame> georeferenced;
  std::string name;  // in messages and the manifest
};

// The texture is read before the DEM's work starts, so a bad image costs nothing.
TextureSource read_texture_source(const BuildArgs& args) {
  TextureSource t;
  if (!args.texture.empty()) t.image = read_texture(args.texture);
  if (!args.texture_mip.empty()) {
    t.mips = read_texture_mip(args.texture_mip);
    t.image = t.mips[0];
  }
  t.name = args.texture_mip.empty() ? args.texture : args.texture_mip + "_0.png";
  return t;
}

void place_texture(TextureSource& t, const BuildArgs& args, const LoadedDem& dem) {
  // A georeferenced image (GeoTIFF, or any image with a world file) on a georeferenced DEM
  // lies where its georeference says, whatever its size.
  if (t.image && t.mips.empty() && !is_stdio(args.texture) && (dem.raster.georeferenced || !args.dem.origin.empty())) {
    formats::RasterGeoreference g;
    try {
      g = formats::read_georeference(args.texture);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;  // GDAL cannot read it: OpenCV did, unplaced
    }
    if (g.georeferenced) {
      const terrainlod::ImageFrame f = terrainlod::georeferenced_frame(
          {dem.origin_x, dem.origin_y, dem.dx, dem.dy, dem.grid.height}, {g.origin_x, g.origin_y, g.dx, g.dy, g.height});
      const int iw = t.image->pixels.cols, ih = t.image->pixels.rows;
      const double px0 = f.ox, px1 = (dem.grid.width - 1) * f.sx + f.ox, py0 = f.oy, py1 = (dem.grid.height - 1) * f.sy + f.oy;
      if (px1 < -0.5 || px0 > iw - 0.5 || py1 < -0.5 || py0 > ih - 0.5)
        throw bad_input("texture's georeference does not overlap the DEM ({})", args.texture);
      t.georeferenced = f;
    }
  }
  if (t.image && !t.georeferenced) {
    try {
      t.placement = terrainlod::place_image(t.image->pixels.cols, t.image->pixels.rows, dem.grid.width, dem.grid.height);
    } catch (const Error& e) {
      throw Error(e.status(), fmt::format("{} ({})", e.what(), t.name));
    }
  }
}

// Finished tiles go to one temporary spill file per level as they come (leaves first);
// the archive is then the head and the levels' blobs in transmission order (root first),
// so memory holds one chunk of tiles, never the pyramid. The files close with this.
struct SpilledLevels {
  struct Level {
    std::FILE* file = nullptr;
    std::vector<TileEntry> entries;
  };
  std::vector<Level> level;
  std::size_t tile_count = 0;

  SpilledLevels() = default;
  SpilledLevels(const SpilledLevels&) = delete;
  SpilledLevels& operator=(const SpilledLevels&) = delete;
  ~SpilledLevels() {
    for (auto& s : level)
      if (s.file) std::fclose(s.file);
  }

  void add(const terrainlod::Tile& t, const std::string& blob) {
    const auto l = static_cast<std::size_t>(t.id.level);
    if (level.size() <= l) level.resize(l + 1);
    if (!level[l].file && !(level[l].file = std::tmpfile())) throw io_error("cannot create a temporary spill file");
    if (std::fwrite(blob.data(), 1, blob.size(), level[l].file) != blob.size())
      throw io_error("cannot write the temporary spill file");
    level[l].entries.push_back({t.id, 0, static_cast<std::uint32_t>(blob.size())});
    ++tile_count;
  }

  // The index: the levels root first, as spilled.
  std::vector<TileEntry> entries() const {
    std::vector<TileEntry> out;
    for (const auto& sp : level) out.insert(out.end(), sp.entries.begin(), sp.entries.end());
    return out;
  }
};

terrainlod::Pyramid build_and_spill(const LoadedDem& dem, const terrainlod::BuildParams& params, const BuildArgs& args,
                                    SpilledLevels& spill) {
  // The tiles done of all the pyramid's tiles: a bar like every tool's (it was a bare count).
  Progress bar("terrainlod build", 0, progress_wanted(args.progress));
  terrainlod::Pyramid pyr = terrainlod::build_pyramid_streaming(
      dem.grid, dem.dx, dem.dy, params, [&](terrainlod::Tile&& t, std::string&& blob) { spill.add(t, blob); },
      [&](std::size_t done, std::size_t total) { bar.set(done, total); });
  bar.finish();
  return pyr;
}

nlohmann::json pyramid_manifest(const BuildArgs& args, const LoadedDem& dem, const terrainlod::Pyramid& pyr,
                                const terrainlod::BuildParams& params, int texels) {
  nlohmann::json levels = nlohmann::json::array();
  for (const auto& lv : pyr.level)
    levels.push_back({{"level", lv.level}, {"tiles_x", lv.tiles_x}, {"tiles_y", lv.tiles_y}, {"cells", lv.cells},
                      {"lattice_bits", lv.lattice_bits}, {"k", lv.k}, {"eps", lv.eps}, {"limit", lv.limit}});
  return {{"format", "terrainlod-pyramid"},
          {"version", 1},
          {"width", dem.grid.width},
          {"height", dem.grid.height},
          {"origin", {dem.origin_x, dem.origin_y}},
          {"cell_size", {dem.dx, dem.dy}},
          {"crs", dem.raster.crs},
          {"tile", args.tile},
          {"texels", texels},
          {"error_fraction", args.error_fraction},
          {"height_quantum", args.height_quantum},
          {"z_quantum", params.z_quantum},
          {"leaf_error", args.leaf_error},
          {"diagonal", diagonal_name(args.dem.diagonal)},
          {"levels", pyr.levels},
          {"padded", pyr.padded},
          {"coding", coding_name(args.coding)},
          {"connectivity", "strips"},
          {"reference", reference_name(args.reference)},
          {"level", levels},
          {"texture", nullptr},
          {"tool", "terrainlod 1"}};
}

// Texture tiles (docs/terrainlod.md, textures): the image (or a hillshade of the DEM)
// resampled to the leaf canvas, box-filtered level by level, cut into T x T tiles; the
// manifest's "texture" says how. None without a texture or --hillshade.
std::vector<std::string> texture_tiles_of(const BuildArgs& args, const LoadedDem& dem, const terrainlod::Pyramid& pyr,
                                          const std::vector<TileEntry>& entries, const TextureSource& tex, int texels,
                                          nlohmann::json& manifest) {
  if (!(args.hillshade || !args.texture.empty() || !tex.mips.empty())) return {};
  const bool hillshade = args.hillshade;
  const cv::Mat pixels = hillshade ? terrainlod::hillshade_image(dem.grid, dem.dx, dem.dy) : tex.image->pixels;
  std::vector<std::string> textures =
      texture_tiles(pyr, entries, pixels, hillshade || !tex.placement ? terrainlod::ImagePlacement::samples : *tex.placement,
                    tex.georeferenced, args, texels, dem, tex.mips);
  manifest["texture"] = {{"format", args.texture_format == TextureFormat::jpeg ? "jpeg" : "png"},
                         {"texels", texels},
                         {"channels", pixels.channels()},
                         {"source", hillshade ? "hillshade" : std::filesystem::path(tex.name).filename().string()},
                         {"placement", tex.georeferenced ? "georeferenced"
                                       : hillshade || *tex.placement == terrainlod::ImagePlacement::samples ? "samples" : "extent"},
                         {"filter", tex.mips.empty() ? "2x2 box mean per level" : "prefiltered pyramid (--texture-mip), one level per tile level"}};
  if (args.texture_format == TextureFormat::jpeg) manifest["texture"]["quality"] = args.texture_quality;
  return textures;
}

// The spilled blobs in index order (the levels' files one after the other), each handed
// to `emit` with its tile's texture and its index entry (the length is the final one).
// Progressive coding recodes each level against the level before it (docs/terrainlod.md
// §4): that level's standalone blobs are kept (coded, small) and only the parents of the
// chunk of rows at hand are decoded.
template <typename Emit>
void for_each_stored_tile(SpilledLevels& spill, const terrainlod::Pyramid& pyr, std::vector<TileEntry>& entries,
                          const std::vector<std::string>& textures, bool progressive, int threads, Emit&& emit) {
  std::string parent_store, level_store;            // standalone blobs of the previous / this level
  std::vector<std::size_t> parent_at, level_at;     // their offsets (one more at the end)
  std::size_t i = 0;
  for (std::size_t l = 0; l < spill.level.size(); ++l) {
    auto& sp = spill.level[l];
    if (!sp.file) continue;  // a level without tiles
    std::rewind(sp.file);
    const int tiles_x = pyr.level[l].tiles_x;
    // Chunks of whole even rows: a parent row serves two child rows.
    const std::size_t rows = static_cast<std::size_t>(std::max(2, 2 * ((8 * threads + 2 * tiles_x - 1) / (2 * tiles_x))));
    level_store.clear();
    level_at.assign(1, 0);
    for (std::size_t first = 0; first < sp.entries.size(); first += rows * static_cast<std::size_t>(tiles_x)) {
      const std::size_t last = std::min(sp.entries.size(), first + rows * static_cast<std::size_t>(tiles_x));
      for (std::size_t k = first; k < last; ++k) {
        const std::size_t at = level_store.size();
        level_store.resize(at + sp.entries[k].length);
        if (std::fread(level_store.data() + at, 1, sp.entries[k].length, sp.file) != sp.entries[k].length)
          throw io_error("cannot read back the temporary spill file");
        level_at.push_back(level_store.size());
      }
      std::vector<std::string> recoded;
      if (progressive && l > 0) {
        std::vector<terrainlod::CodedTile> children, parents;
        for (std::size_t k = first; k < last; ++k)
          children.push_back({sp.entries[k].id, std::string_view(level_store).substr(level_at[k], level_at[k + 1] - level_at[k])});
        const std::size_t ptx = static_cast<std::size_t>(pyr.level[l - 1].tiles_x);
        const std::size_t p0 = static_cast<std::size_t>(sp.entries[first].id.y / 2) * ptx;
        const std::size_t p1 = std::min(parent_at.size() - 1, static_cast<std::size_t>(sp.entries[last - 1].id.y / 2 + 1) * ptx);
        for (std::size_t k = p0; k < p1; ++k)
          parents.push_back({spill.level[l - 1].entries[k].id, std::string_view(parent_store).substr(parent_at[k], parent_at[k + 1] - parent_at[k])});
        recoded = terrainlod::recode_progressive(children, parents, threads);
      }
      for (std::size_t k = first; k < last; ++k, ++i) {
        const std::string_view blob = recoded.empty() ? std::string_view(level_store).substr(level_at[k], level_at[k + 1] - level_at[k])
                                                      : std::string_view(recoded[k - first]);
        entries[i].length = static_cast<std::uint32_t>(blob.size());
        emit(entries[i], blob, textures.empty() ? std::string_view() : std::string_view(textures[i]));
      }
    }
    parent_store.swap(level_store);
    parent_at.swap(level_at);
  }
}

// The .tlp archive; returns its size in bytes. The index holds each tile's final length,
// known only once it is recoded: the head is written as a placeholder of its (fixed) size
// and filled in at the end.
template <typename ForEachTile>
std::uint64_t write_archive(const std::string& path, const nlohmann::json& manifest, const std::vector<TileEntry>& entries,
                            std::string_view nodata, ForEachTile&& for_each_tile) {
  std::string head = terrainlod::encode_tlp_head(manifest.dump(), entries, nodata);
  AtomicFile out(path);
  std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
  if (!f) throw io_error("cannot write {}", path);
  bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
  std::uint64_t file_bytes = head.size();
  try {
    for_each_tile([&](const TileEntry&, std::string_view blob, std::string_view texture) {
      ok = ok && std::fwrite(blob.data(), 1, blob.size(), f) == blob.size();
      // An empty view may hold a null pointer, which fwrite must not get.
      if (!texture.empty()) ok = ok && std::fwrite(texture.data(), 1, texture.size(), f) == texture.size();
      file_bytes += blob.size() + texture.size();
    });
    const std::string final_head = terrainlod::encode_tlp_head(manifest.dump(), entries, nodata);
    if (final_head.size() != head.size()) throw runtime_failure("archive head changed size");
    ok = ok && std::fseek(f, 0, SEEK_SET) == 0 && std::fwrite(final_head.data(), 1, final_head.size(), f) == final_head.size();
  } catch (...) {
    std::fclose(f);
    throw;
  }
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) throw io_error("cannot write {}", path);
  out.commit();
  return file_bytes;
}

// The pyramid as a directory of tile files; returns the tiles' bytes.
template <typename ForEachTile>
std::uint64_t write_directory(const BuildArgs& args, const nlohmann::json& manifest, std::string_view nodata, ForEachTile&& for_each_tile) {
  std::uint64_t file_bytes = nodata.size();
  DirectoryPyramidWriter out(args.output, manifest, args.texture_format == TextureFormat::jpeg ? "jpg" : "png");
  if (!nodata.empty()) out.add_nodata(nodata);
  for_each_tile([&](const TileEntry& e, std::string_view blob, std::string_view texture) {
    out.add(e.id, blob, texture);
    file_bytes += blob.size() + texture.size();
  });
  out.commit();
  return file_bytes;
}

// What --report holds: counts, sizes and the stages' times.
struct BuildFigures {
  std::size_t tiles = 0;
  std::uint64_t file_bytes = 0;
  std::size_t texture_bytes = 0;
  bool archive = false;
  std::size_t nodata_samples = 0, nodata_bytes = 0;  // --nodata hole: the mask
  std::string nodata_mode = "fill";
  double read_ms = 0, build_ms = 0, texture_ms = 0, write_ms = 0;
  int threads = 0;
};

void write_build_report(const std::string& path, const BuildFigures& b) {
  nlohmann::json r = {{"tiles", b.tiles},
                      {"bytes", b.file_bytes},
                      {"texture_bytes", b.texture_bytes},
                      {"container", b.archive ? "archive" : "directory"},
                      {"time_ms", {{"read", b.read_ms}, {"build", b.build_ms}, {"texture", b.texture_ms}, {"write", b.write_ms}}},
                      {"threads", b.threads},
                      {"nodata", {{"mode", b.nodata_mode}, {"samples", b.nodata_samples}, {"mask_bytes", b.nodata_bytes}}},
                      {"peak_rss_kb", peak_rss_kb()}};
  write_output(path, r.dump(2) + "\n");
}

}  // namespace

int run_build(const BuildArgs& args) {
  if (args.output.empty() || is_stdio(args.output)) throw usage_error("build needs -o PYRAMID.tlp or -o DIRECTORY/");
  BuildFigures fig;
  fig.archive = args.output.size() >= 4 && args.output.substr(args.output.size() - 4) == ".tlp";
  terrainlod::BuildParams params = build_params(args);
  fig.threads = params.threads;
  fig.nodata_mode = nodata_mode_name(args.dem.nodata_mode);

  const auto t0 = SteadyClock::now();
  TextureSource tex = read_texture_source(args);
  const LoadedDem dem = load_dem(args.dem);
  place_texture(tex, args, dem);
  fig.read_ms = ms_since(t0);
  const bool integer = dem.raster.integer && args.dem.z_scale == 1 && std::floor(args.dem.z_offset) == args.dem.z_offset;
  params.z_quantum = args.z_quantum > 0 ? args.z_quantum : integer ? 1.0 : 0.01;
  check_quantum_options(args.height_quantum, args.leaf_error);

  const auto t1 = SteadyClock::now();
  SpilledLevels spill;
  const terrainlod::Pyramid pyr = build_and_spill(dem, params, args, spill);
  fig.tiles = spill.tile_count;
  fig.build_ms = ms_since(t1);
  std::vector<TileEntry> entries = spill.entries();

  const int texels = args.texels == 0 ? args.tile : args.texels;
  nlohmann::json manifest = pyramid_manifest(args, dem, pyr, params, texels);
  const auto t3 = SteadyClock::now();
  const std::vector<std::string> textures = texture_tiles_of(args, dem, pyr, entries, tex, texels, manifest);
  for (const auto& t : textures) fig.texture_bytes += t.size();
  fig.texture_ms = ms_since(t3);
  for (std::size_t i = 0; i < textures.size(); ++i) entries[i].texture_length = static_cast<std::uint32_t>(textures[i].size());

  const auto t2 = SteadyClock::now();
  auto for_each_tile = [&](auto&& emit) {
    for_each_stored_tile(spill, pyr, entries, textures, args.coding == Coding::progressive, params.threads, emit);
  };
  // --nodata hole: the geometry is the filled one; the mask says where nothing is drawn
  // (docs/terrainlod.md §5, holes). Filled pyramids have no section and keep their bytes.
  std::string nodata;
  if (args.dem.nodata_mode == NodataMode::hole) {
    const terrainlod::NodataMask mask = terrainlod::nodata_mask(dem.grid);
    nodata = terrainlod::encode_nodata_mask(mask);
    manifest["version"] = 2;
    manifest["nodata"] = "hole";
    manifest["nodata_samples"] = mask.samples;
    fig.nodata_samples = mask.samples;
    fig.nodata_bytes = nodata.size();
  }
  fig.file_bytes = fig.archive ? write_archive(args.output, manifest, entries, nodata, for_each_tile)
                               : write_directory(args, manifest, nodata, for_each_tile);
  fig.write_ms = ms_since(t2);
  if (!args.report.empty()) write_build_report(args.report, fig);
  return 0;
}

}  // namespace fest::terrainlod_tool

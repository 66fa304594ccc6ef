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

}  // namespace

int run_build(const BuildArgs& args) {
  if (args.output.empty() || is_stdio(args.output)) throw usage_error("build needs -o PYRAMID.tlp or -o DIRECTORY/");
  const bool archive = args.output.size() >= 4 && args.output.substr(args.output.size() - 4) == ".tlp";
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

  const auto t0 = SteadyClock::now();
  // The texture is read before the DEM's work starts, so a bad image costs nothing.
  std::optional<Image> texture_image;
  std::vector<Image> mips;
  if (!args.texture.empty()) texture_image = read_texture(args.texture);
  if (!args.texture_mip.empty()) {
    mips = read_texture_mip(args.texture_mip);
    texture_image = mips[0];
  }
  const LoadedDem dem = load_dem(args.dem);
  std::optional<terrainlod::ImagePlacement> placement;
  std::optional<terrainlod::ImageFrame> georeferenced;
  const std::string texture_name = args.texture_mip.empty() ? args.texture : args.texture_mip + "_0.png";
  // A georeferenced image (GeoTIFF, or any image with a world file) on a georeferenced DEM
  // lies where its georeference says, whatever its size.
  if (texture_image && mips.empty() && !is_stdio(args.texture) && (dem.raster.georeferenced || !args.dem.origin.empty())) {
    formats::RasterGeoreference g;
    try {
      g = formats::read_georeference(args.texture);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;  // GDAL cannot read it: OpenCV did, unplaced
    }
    if (g.georeferenced) {
      const terrainlod::ImageFrame f = terrainlod::georeferenced_frame(
          {dem.origin_x, dem.origin_y, dem.dx, dem.dy, dem.grid.height}, {g.origin_x, g.origin_y, g.dx, g.dy, g.height});
      const int iw = texture_image->pixels.cols, ih = texture_image->pixels.rows;
      const double px0 = f.ox, px1 = (dem.grid.width - 1) * f.sx + f.ox, py0 = f.oy, py1 = (dem.grid.height - 1) * f.sy + f.oy;
      if (px1 < -0.5 || px0 > iw - 0.5 || py1 < -0.5 || py0 > ih - 0.5)
        throw bad_input("texture's georeference does not overlap the DEM ({})", args.texture);
      georeferenced = f;
    }
  }
  if (texture_image && !georeferenced) {
    try {
      placement = terrainlod::place_image(texture_image->pixels.cols, texture_image->pixels.rows, dem.grid.width, dem.grid.height);
    } catch (const Error& e) {
      throw Error(e.status(), fmt::format("{} ({})", e.what(), texture_name));
    }
  }
  const double read_ms = ms_since(t0);
  const bool integer = dem.raster.integer && args.dem.z_scale == 1 && std::floor(args.dem.z_offset) == args.dem.z_offset;
  params.z_quantum = args.z_quantum > 0 ? args.z_quantum : integer ? 1.0 : 0.01;
  check_quantum_options(args.height_quantum, args.leaf_error);

  const auto t1 = SteadyClock::now();
  Progress bar("build", 0, progress_wanted(args.progress));
  // Finished tiles go to one temporary spill file per level as they come (leaves first);
  // the archive is then the head and the levels' blobs in transmission order (root first),
  // so memory holds one chunk of tiles, never the pyramid.
  struct Spill {
    std::FILE* file = nullptr;
    std::vector<TileEntry> entries;
  };
  std::vector<Spill> spill;
  auto close_spills = [&] {
    for (auto& s : spill)
      if (s.file) std::fclose(s.file);
  };
  std::size_t tile_count = 0;
  terrainlod::Pyramid pyr;
  try {
    pyr = terrainlod::build_pyramid_streaming(
        dem.grid, dem.dx, dem.dy, params,
        [&](terrainlod::Tile&& t, std::string&& blob) {
          const auto l = static_cast<std::size_t>(t.id.level);
          if (spill.size() <= l) spill.resize(l + 1);
          if (!spill[l].file && !(spill[l].file = std::tmpfile())) throw io_error("cannot create a temporary spill file");
          if (std::fwrite(blob.data(), 1, blob.size(), spill[l].file) != blob.size())
            throw io_error("cannot write the temporary spill file");
          spill[l].entries.push_back({t.id, 0, static_cast<std::uint32_t>(blob.size())});
          ++tile_count;
        },
        [&](std::size_t done, std::size_t) { bar.set(done); });
  } catch (...) {
    close_spills();
    throw;
  }
  bar.finish();
  const double build_ms = ms_since(t1);
  std::vector<TileEntry> entries;  // index order: the levels root first, as spilled
  for (const auto& sp : spill) entries.insert(entries.end(), sp.entries.begin(), sp.entries.end());

  nlohmann::json levels = nlohmann::json::array();
  for (const auto& lv : pyr.level)
    levels.push_back({{"level", lv.level}, {"tiles_x", lv.tiles_x}, {"tiles_y", lv.tiles_y}, {"cells", lv.cells},
                      {"lattice_bits", lv.lattice_bits}, {"k", lv.k}, {"eps", lv.eps}, {"limit", lv.limit}});
  const int texels = args.texels == 0 ? args.tile : args.texels;
  nlohmann::json manifest = {{"format", "terrainlod-pyramid"},
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
  // Texture tiles (docs/terrainlod.md, textures): the image (or a hillshade of the DEM) resampled to the
  // leaf canvas, box-filtered level by level, cut into T x T tiles.
  const auto t3 = SteadyClock::now();
  std::vector<std::string> textures;
  std::size_t texture_bytes = 0;
  if (args.hillshade || !args.texture.empty() || !mips.empty()) {
    const bool hillshade = args.hillshade;
    const cv::Mat pixels = hillshade ? terrainlod::hillshade_image(dem.grid, dem.dx, dem.dy) : texture_image->pixels;
    textures = texture_tiles(pyr, entries, pixels, hillshade || !placement ? terrainlod::ImagePlacement::samples : *placement, georeferenced,
                             args, texels, dem, mips);
    for (const auto& t : textures) texture_bytes += t.size();
    manifest["texture"] = {{"format", args.texture_format == TextureFormat::jpeg ? "jpeg" : "png"},
                           {"texels", texels},
                           {"channels", pixels.channels()},
                           {"source", hillshade ? "hillshade" : std::filesystem::path(texture_name).filename().string()},
                           {"placement", georeferenced ? "georeferenced"
                                         : hillshade || *placement == terrainlod::ImagePlacement::samples ? "samples" : "extent"},
                           {"filter", mips.empty() ? "2x2 box mean per level" : "prefiltered pyramid (--texture-mip), one level per tile level"}};
    if (args.texture_format == TextureFormat::jpeg) manifest["texture"]["quality"] = args.texture_quality;
  }
  const double texture_ms = ms_since(t3);
  for (std::size_t i = 0; i < textures.size(); ++i) entries[i].texture_length = static_cast<std::uint32_t>(textures[i].size());
  const auto t2 = SteadyClock::now();
  std::uint64_t file_bytes = 0;
  try {
    // The spilled blobs in index order (the levels' files one after the other), each
    // handed to `emit` with its tile's texture and its index entry (the length is the
    // final one). Progressive coding recodes each level against the level before it
    // (docs/terrainlod.md §4): that level's standalone blobs are kept (coded, small) and only the
    // parents of the chunk of rows at hand are decoded.
    const bool progressive = args.coding == Coding::progressive;
    auto for_each_tile = [&](auto&& emit) {
      std::string parent_store, level_store;            // standalone blobs of the previous / this level
      std::vector<std::size_t> parent_at, level_at;     // their offsets (one more at the end)
      std::size_t i = 0;
      for (std::size_t l = 0; l < spill.size(); ++l) {
        auto& sp = spill[l];
        if (!sp.file) continue;  // a level without tiles
        std::rewind(sp.file);
        const int tiles_x = pyr.level[l].tiles_x;
        // Chunks of whole even rows: a parent row serves two child rows.
        const std::size_t rows = static_cast<std::size_t>(std::max(2, 2 * ((8 * params.threads + 2 * tiles_x - 1) / (2 * tiles_x))));
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
              parents.push_back({spill[l - 1].entries[k].id, std::string_view(parent_store).substr(parent_at[k], parent_at[k + 1] - parent_at[k])});
            recoded = terrainlod::recode_progressive(children, parents, params.threads);
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
    };
    if (archive) {
      // The index holds each tile's final length, known only once it is recoded: the head
      // is written as a placeholder of its (fixed) size and filled in at the end.
      std::string head = terrainlod::encode_tlp_head(manifest.dump(), entries);
      AtomicFile out(args.output);
      std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
      if (!f) throw io_error("cannot write {}", args.output);
      bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
      file_bytes = head.size();
      try {
        for_each_tile([&](const TileEntry&, std::string_view blob, std::string_view texture) {
          ok = ok && std::fwrite(blob.data(), 1, blob.size(), f) == blob.size();
          // An empty view may hold a null pointer, which fwrite must not get.
          if (!texture.empty()) ok = ok && std::fwrite(texture.data(), 1, texture.size(), f) == texture.size();
          file_bytes += blob.size() + texture.size();
        });
        const std::string final_head = terrainlod::encode_tlp_head(manifest.dump(), entries);
        if (final_head.size() != head.size()) throw runtime_failure("archive head changed size");
        ok = ok && std::fseek(f, 0, SEEK_SET) == 0 && std::fwrite(final_head.data(), 1, final_head.size(), f) == final_head.size();
      } catch (...) {
        std::fclose(f);
        throw;
      }
      ok = (std::fclose(f) == 0) && ok;
      if (!ok) throw io_error("cannot write {}", args.output);
      out.commit();
    } else {
      DirectoryPyramidWriter out(args.output, manifest, args.texture_format == TextureFormat::jpeg ? "jpg" : "png");
      for_each_tile([&](const TileEntry& e, std::string_view blob, std::string_view texture) {
        out.add(e.id, blob, texture);
        file_bytes += blob.size() + texture.size();
      });
      out.commit();
    }
  } catch (...) {
    close_spills();
    throw;
  }
  close_spills();
  const double write_ms = ms_since(t2);
  if (!args.report.empty()) {
    nlohmann::json r = {{"tiles", tile_count},
                        {"bytes", file_bytes},
                        {"texture_bytes", texture_bytes},
                        {"container", archive ? "archive" : "directory"},
                        {"time_ms", {{"read", read_ms}, {"build", build_ms}, {"texture", texture_ms}, {"write", write_ms}}},
                        {"threads", params.threads},
                        {"peak_rss_kb", peak_rss_kb()}};
    write_output(args.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::terrainlod_tool

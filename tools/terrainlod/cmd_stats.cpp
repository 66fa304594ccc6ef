// terrainlod stats: JSON statistics of a pyramid (tiles, bytes per level, both codings), or of a DEM
// and the pyramid plan it would get.

#include "commands.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "dem_input.hpp"
#include "pyramid_options.hpp"
#include "pyramid_view.hpp"
#include "terrainlod/progressive_recode.hpp"
#include "terrainlod/pyramid_plan.hpp"
#include "terrainlod/tile_codec.hpp"

namespace fest::terrainlod_tool {

int run_pyramid_stats(const std::string& path, bool progress) {
  PyramidFile pyr = open_pyramid(path);
  Progress bar("terrainlod stats", pyr.index().size(), progress_wanted(progress));
  const int L = pyr.layout().levels;
  struct Acc {
    std::size_t tiles = 0, vertices = 0, border = 0, triangles = 0, header = 0, vert = 0, conn = 0, refine = 0, texture = 0;
    std::size_t standalone = 0, progressive = 0, progressive_tiles = 0, inherited_present = 0;
    double worst = 0;
  };
  std::vector<Acc> acc(static_cast<std::size_t>(L) + 1);
  int level_at = -1;
  for (const auto& e : pyr.index()) {
    if (e.id.level != level_at) keep_parents_only(pyr, level_at = e.id.level);
    const auto& t = pyr.tile(e.id);
    auto& a = acc[static_cast<std::size_t>(e.id.level)];
    ++a.tiles;
    a.vertices += t.vertices.size();
    a.border += 4 * static_cast<std::size_t>(t.n());
    a.triangles += t.triangles.size();
    // Both codings of the tile with its stream's strip order (docs/terrainlod.md §4: stats give
    // both sizes): the stored one is one of them, byte for byte (verify checks that).
    const std::string_view bytes = pyr.tile_bytes(e.id);
    const terrainlod::Tile* parent =
        e.id.level > 0 && pyr.has(terrainlod::parent_id(e.id)) ? &pyr.tile(terrainlod::parent_id(e.id)) : nullptr;
    terrainlod::TileSizes alone, prog;
    terrainlod::recode_tile(bytes, terrainlod::TileCoding::standalone, parent, &alone);
    terrainlod::recode_tile(bytes, terrainlod::TileCoding::progressive, parent, &prog);
    const terrainlod::TileSizes& s = terrainlod::tile_coding(bytes) == terrainlod::TileCoding::progressive ? prog : alone;
    a.header += s.header, a.vert += s.vertices, a.conn += s.connectivity, a.refine += s.refinement;
    a.standalone += alone.total(), a.progressive += prog.total();
    if (prog.coding == terrainlod::TileCoding::progressive) ++a.progressive_tiles, a.inherited_present += prog.inherited_present;
    a.texture += e.texture_length;
    if (t.eps > 0) a.worst = std::max(a.worst, static_cast<double>(t.err) / t.eps);
    bar.advance();
  }
  bar.finish();
  nlohmann::json levels = nlohmann::json::array();
  std::size_t total_v = 0, total_bytes = 0, total_t = 0, total_texture = 0, total_alone = 0, total_prog = 0;
  auto per_vertex = [](std::size_t bytes, std::size_t vertices) { return vertices ? static_cast<double>(bytes) / vertices : 0.0; };
  for (int l = 0; l <= L; ++l) {
    const auto& a = acc[static_cast<std::size_t>(l)];
    const auto& m = pyr.manifest().at("level").at(static_cast<std::size_t>(l));
    const std::size_t bytes_l = a.header + a.vert + a.conn + a.refine;
    total_v += a.vertices, total_bytes += bytes_l, total_t += a.triangles, total_texture += a.texture;
    total_alone += a.standalone, total_prog += a.progressive;
    levels.push_back({{"level", l},
                      {"tiles", a.tiles},
                      {"vertices", a.vertices},
                      {"border_vertices", a.border},
                      {"triangles", a.triangles},
                      {"eps", m.at("eps")},
                      {"lattice_bits", m.at("lattice_bits")},
                      {"bytes", {{"total", bytes_l}, {"header", a.header}, {"vertices", a.vert}, {"connectivity", a.conn},
                                 {"refinement", a.refine}, {"texture", a.texture}}},
                      {"bytes_per_vertex", per_vertex(bytes_l, a.vertices)},
                      {"standalone_bytes", a.standalone},
                      {"progressive_bytes", a.progressive},
                      {"progressive_tiles", a.progressive_tiles},
                      {"inherited_vertices_kept", a.inherited_present},
                      {"max_err_over_eps", l == L ? nlohmann::json(nullptr) : nlohmann::json(a.worst)}});
  }
  const double samples = pyr.manifest().at("width").get<double>() * pyr.manifest().at("height").get<double>();
  nlohmann::json j = {{"manifest", pyr.manifest()},
                      {"level", levels},
                      {"totals",
                       {{"tiles", pyr.index().size()},
                        {"vertices", total_v},
                        {"triangles", total_t},
                        {"coding", pyr.manifest().value("coding", std::string("standalone"))},
                        {"tile_bytes", total_bytes},
                        {"standalone_tile_bytes", total_alone},
                        {"progressive_tile_bytes", total_prog},
                        {"texture_bytes", total_texture},
                        {"file_bytes", pyr.size()},
                        {"bytes_per_vertex", per_vertex(total_bytes, total_v)},
                        {"standalone_bytes_per_vertex", per_vertex(total_alone, total_v)},
                        {"progressive_bytes_per_vertex", per_vertex(total_prog, total_v)},
                        {"bytes_per_sample", static_cast<double>(total_bytes) / samples},
                        {"ratio_to_raw_int16", static_cast<double>(total_bytes) / (2 * samples)}}}};
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

int run_stats(const StatsArgs& args) {
  // A pyramid archive gets its own statistics; anything else is read as a DEM.
  if (!is_stdio(args.dem.path)) {
    std::error_code ec;
    if (std::filesystem::is_directory(args.dem.path, ec)) return run_pyramid_stats(args.dem.path, args.progress);
    std::string head = read_input(args.dem.path);
    if (head.size() >= 4 && head.compare(0, 4, "FTLP") == 0) return run_pyramid_stats(args.dem.path, args.progress);
  }
  terrainlod::PyramidParams params;
  params.tile = args.tile;
  params.texels = args.texels;
  params.error_fraction = args.error_fraction;
  // Parameter checks first (usage errors before reading anything).
  check_tile_options(params.tile, params.texels, params.error_fraction);
  const LoadedDem dem = load_dem(args.dem);
  const terrainlod::PyramidPlan plan = terrainlod::plan_pyramid(dem.grid.width, dem.grid.height, dem.dx, dem.dy, params);
  nlohmann::json levels = nlohmann::json::array();
  for (const auto& l : plan.level)
    levels.push_back({{"level", l.level},
                      {"tiles_x", l.tiles_x},
                      {"tiles_y", l.tiles_y},
                      {"tile_side", {l.side_x, l.side_y}},
                      {"eps", l.eps},
                      {"bound", l.bound}});
  const double padded = static_cast<double>(plan.padded) * plan.padded;
  nlohmann::json j = {{"dem", dem_json(dem)},
                      {"tile", params.tile},
                      {"texels", params.texels == 0 ? params.tile : params.texels},
                      {"error_fraction", params.error_fraction},
                      {"levels", plan.levels},
                      {"padded_size", plan.padded},
                      {"padded_share", 1.0 - static_cast<double>(dem.grid.size()) / padded},
                      {"level", levels}};
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}


}  // namespace fest::terrainlod_tool

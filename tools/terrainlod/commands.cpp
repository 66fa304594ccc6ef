// The subcommands: read with formats/, compute with lib/terrainlod, write with formats/.

#include "commands.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/file_io.hpp"
#include "core/mesh.hpp"
#include "dem_input.hpp"
#include "pyramid_options.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "terrainlod/pyramid_plan.hpp"
#include "terrainlod/simplify.hpp"

namespace fest::terrainlod_tool {
namespace {

// Grid units -> world coordinates of the DEM (x east, y north, z up).
Mesh world_mesh(const terrainlod::Tin& tin, const LoadedDem& dem) {
  Mesh mesh;
  for (const auto& p : tin.vertices)
    mesh.add_vertex(Mesh::Point(dem.origin_x + p.x * dem.dx, dem.origin_y + p.y * dem.dy, p.z));
  for (const auto& t : tin.triangles)
    mesh.add_face(Mesh::VertexHandle(t[0]), Mesh::VertexHandle(t[1]), Mesh::VertexHandle(t[2]));
  return mesh;
}

nlohmann::json dem_json(const LoadedDem& dem) {
  const auto& r = dem.raster;
  nlohmann::json j = {{"format", r.format},
                      {"width", r.width},
                      {"height", r.height},
                      {"integer", r.integer},
                      {"georeferenced", r.georeferenced},
                      {"origin", {dem.origin_x, dem.origin_y}},
                      {"cell_size", {dem.dx, dem.dy}},
                      {"nodata_samples", dem.condition.nodata},
                      {"z_min", dem.condition.z_min},
                      {"z_max", dem.condition.z_max}};
  j["nodata_value"] = r.nodata && std::isfinite(*r.nodata) ? nlohmann::json(*r.nodata) : nlohmann::json(nullptr);
  j["crs"] = r.crs.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.crs);
  return j;
}

}  // namespace

int run_simplify(const SimplifyArgs& args) {
  if (!(args.max_error >= 0) || !std::isfinite(args.max_error))
    throw usage_error("--max-error must be a finite number >= 0 (got {})", args.max_error);
  // The output format is settled before any work, so a bad -o/--to costs nothing.
  formats::OutputFormat out = !args.to.empty() ? formats::output_format_from_name(args.to)
                              : is_stdio(args.output) ? formats::OutputFormat{formats::Format::ply, false}
                                                      : formats::output_format_from_path(args.output);
  if (formats::kind_of(out.format) != formats::Kind::mesh)
    throw usage_error("output must be a mesh format (ply, obj, off, stl, drc), not {}", formats::format_name(out.format));

  const auto t0 = SteadyClock::now();
  const LoadedDem dem = load_dem(args.dem);
  const double read_ms = ms_since(t0);

  const auto t1 = SteadyClock::now();
  terrainlod::SimplifyOptions options;
  options.max_error = args.max_error;
  options.diagonal = args.dem.diagonal;
  options.start = args.start;
  const terrainlod::SimplifyResult result = terrainlod::simplify_grid(dem.grid, options);
  const double simplify_ms = ms_since(t1);

  const std::string bytes = formats::write_mesh(world_mesh(result.mesh, dem), out.format);
  nlohmann::json report = {{"dem", dem_json(dem)},
                           {"max_error", args.max_error},
                           {"diagonal", diagonal_name(args.dem.diagonal)},
                           {"start", start_name(args.start)},
                           {"vertices", result.mesh.vertices.size()},
                           {"triangles", result.mesh.triangles.size()},
                           {"collapses", result.collapses},
                           {"max_collapse_error", result.max_error},
                           {"tolerance", result.tolerance},
                           {"time_ms", {{"read", read_ms}, {"simplify", simplify_ms}}}};
  if (!args.report.empty()) {
    // The bound is re-measured triangle by triangle for the report (an independent pass
    // over the final mesh, not the engine's bookkeeping).
    const terrainlod::ReferenceSurface ref(dem.grid, options.diagonal);
    report["measured_error"] = terrainlod::tin_error(ref, result.mesh);
  }
  formats::store_output(args.output, bytes, out.gzip);
  if (!args.report.empty()) write_output(args.report, report.dump(2) + "\n");
  return 0;
}

int run_stats(const StatsArgs& args) {
  // A pyramid archive gets its own statistics; anything else is read as a DEM.
  if (!is_stdio(args.dem.path)) {
    std::error_code ec;
    if (std::filesystem::is_directory(args.dem.path, ec)) return run_pyramid_stats(args.dem.path);
    std::string head = read_input(args.dem.path);
    if (head.size() >= 4 && head.compare(0, 4, "FTLP") == 0) return run_pyramid_stats(args.dem.path);
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

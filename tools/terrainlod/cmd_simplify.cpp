// terrainlod simplify: the whole DEM -> one mesh within the vertical error bound (docs/terrainlod.md),
// the bound re-measured for the report.

#include "commands.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/mesh.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "dem_input.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "terrainlod/nodata_mask.hpp"
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

}  // namespace

int run_simplify(const SimplifyArgs& args) {
  if (!(args.max_error >= 0) || !std::isfinite(args.max_error))
    throw usage_error("--max-error must be a finite number >= 0 (got {})", args.max_error);
  // The output format is settled before any work, so a bad -o/--to costs nothing.
  const formats::OutputFormat out = mesh_output(args.output, args.to);

  const auto t0 = SteadyClock::now();
  const LoadedDem dem = load_dem(args.dem);
  const double read_ms = ms_since(t0);

  const auto t1 = SteadyClock::now();
  terrainlod::SimplifyOptions options;
  options.max_error = args.max_error;
  options.diagonal = args.dem.diagonal;
  options.start = args.start;
  Progress bar("terrainlod simplify", 0, progress_wanted(args.progress));
  options.progress = bar.callback();
  const terrainlod::SimplifyResult result = terrainlod::simplify_grid(dem.grid, options);
  bar.finish();
  const double simplify_ms = ms_since(t1);

  // --nodata hole: the triangles over nodata samples are left out (docs/terrainlod.md §5,
  // holes), and the vertices only they used.
  terrainlod::Tin drawn = result.mesh;
  std::size_t hole_triangles = 0;
  if (args.dem.nodata_mode == NodataMode::hole) {
    const terrainlod::NodataMask mask = terrainlod::nodata_mask(dem.grid);
    terrainlod::TileTriangulation tri;
    for (const auto& p : result.mesh.vertices) tri.vertices.push_back({std::llround(p.x), std::llround(p.y), p.z});
    tri.triangles = result.mesh.triangles;
    hole_triangles = terrainlod::cut_holes(mask, tri);
    drawn.vertices.clear();
    for (const auto& v : tri.vertices) drawn.vertices.push_back({static_cast<double>(v.gx), static_cast<double>(v.gy), v.z});
    drawn.triangles = tri.triangles;
  }
  const std::string bytes = formats::write_mesh(world_mesh(drawn, dem), out.format);
  nlohmann::json report = {{"dem", dem_json(dem)},
                           {"max_error", args.max_error},
                           {"diagonal", diagonal_name(args.dem.diagonal)},
                           {"start", start_name(args.start)},
                           {"vertices", drawn.vertices.size()},
                           {"triangles", drawn.triangles.size()},
                           {"nodata", nodata_mode_name(args.dem.nodata_mode)},
                           {"hole_triangles", hole_triangles},
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


}  // namespace fest::terrainlod_tool

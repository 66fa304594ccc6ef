// terrainlod: multiresolution terrain with a guaranteed vertical error per tile
// (specs/terrainlod.md). This first step has `simplify` (one free tile, exact error) and
// `stats` (the DEM as read and the pyramid's level plan).
//
// Wiring only: this file maps flags onto commands.hpp.

#include <string>

#include "cli/cli.hpp"
#include "commands.hpp"

namespace {

using namespace fest::terrainlod_tool;

void add_dem_options(CLI::App* cmd, DemArgs& d) {
  cmd->add_option("dem", d.path,
                  "DEM: GeoTIFF, ESRI ASCII grid, 16-bit PNG/PGM, .npy, PFM or any raster GDAL reads; - = standard input")
      ->required();
  cmd->add_option("--cell-size", d.cell_size, "Sample spacing dx[,dy] in world units (overrides the file)");
  cmd->add_option("--origin", d.origin, "x0,y0: world position of the south-west sample (overrides the file)");
  cmd->add_option("--z-scale", d.z_scale, "Height = value x scale + offset");
  cmd->add_option("--z-offset", d.z_offset, "Height = value x scale + offset");
  cmd->add_option("--nodata", d.nodata, "Nodata value (overrides the file's); nan accepts NaN heights as nodata");
  cmd->add_option("--diagonal", d.diagonal, "Finest triangulation: short (3-D shorter diagonal), alternate, ne")
      ->check(CLI::IsMember({"short", "alternate", "ne"}));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Multiresolution terrain from a DEM with a guaranteed vertical error: simplify a DEM to a\n"
               "triangle mesh within a bound, report a DEM and its tile pyramid.",
               "terrainlod"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  SimplifyArgs simplify;
  auto* s = app.add_subcommand("simplify", "Simplify the whole DEM to a mesh within --max-error (vertical, exact)");
  add_dem_options(s, simplify.dem);
  s->add_option("--max-error", simplify.max_error, "Largest vertical distance from the DEM surface (height units)")
      ->required();
  s->add_option("-o,--output", simplify.output, "Mesh file (.ply .obj .off .stl .drc); - = standard output (PLY)");
  s->add_option("--to", simplify.to, "Output format: ply, obj, off, stl or drc");
  s->add_option("--report", simplify.report, "JSON report: counts, times, the re-measured error");

  StatsArgs stats;
  auto* st = app.add_subcommand("stats", "The DEM as read (size, georeference, nodata) and its pyramid plan, as JSON");
  add_dem_options(st, stats.dem);
  st->add_option("--tile", stats.tile, "Leaf tile size B in DEM cells (power of two, 4..4096)");
  st->add_option("--texels", stats.texels, "Texels per tile side T (power of two >= B; default B)");
  st->add_option("--error-fraction", stats.error_fraction, "Allowed error per tile in texels (f)");

  return fest::cli::run(app, argc, argv, [&] {
    if (s->parsed()) return run_simplify(simplify);
    return run_stats(stats);
  });
}

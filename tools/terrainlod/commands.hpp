#pragma once
// terrainlod subcommands: formats/dem -> lib/terrainlod -> formats/mesh, JSON.

#include <optional>
#include <string>

namespace fest::terrainlod_tool {

// How a DEM file becomes heights on a grid (spec terrainlod 2.11).
struct DemArgs {
  std::string path;
  std::string cell_size;   // "dx" or "dx,dy"; overrides the file's georeference
  std::string origin;      // "x0,y0": centre of the south-west sample
  double z_scale = 1, z_offset = 0;
  std::string nodata;      // a number, or "nan" to accept NaN heights as nodata
  std::string diagonal = "short";
};

struct SimplifyArgs {
  DemArgs dem;
  double max_error = -1;
  std::string output = "-";
  std::string to;
  std::string report;
  bool quiet = false;
};

struct StatsArgs {
  DemArgs dem;
  int tile = 64;
  int texels = 0;
  double error_fraction = 1.0;
};

int run_simplify(const SimplifyArgs& args);
int run_stats(const StatsArgs& args);

}  // namespace fest::terrainlod_tool

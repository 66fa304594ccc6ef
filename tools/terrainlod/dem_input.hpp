#pragma once
// A DEM file plus the georeference flags -> the library's HeightGrid (south-west origin,
// nodata filled) and the world mapping of its samples.

#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "formats/dem/dem_io.hpp"
#include "terrainlod/height_grid.hpp"
#include "terrainlod/reference_surface.hpp"

namespace fest::terrainlod_tool {

struct LoadedDem {
  formats::DemRaster raster;       // as read (values moved into grid)
  terrainlod::HeightGrid grid;
  terrainlod::ConditionReport condition;
  double origin_x = 0, origin_y = 0, dx = 1, dy = 1;
  std::string name;                // for messages
};

LoadedDem load_dem(const DemArgs& args);
terrainlod::DiagonalRule diagonal_rule(const std::string& name);
// The DEM as the reports describe it: format, size, georeference, nodata, height range.
nlohmann::json dem_json(const LoadedDem& dem);

}  // namespace fest::terrainlod_tool

#pragma once
// Loads fest's GDAL plugin (gdal_plugin_api.h) on first use, so that only an input that
// needs GDAL maps GDAL into the process.

#include "formats/dem/gdal_plugin_api.h"

namespace fest::formats::dem_detail {

struct GdalPlugin {
  int (*open_raster)(const char*, const void*, size_t, size_t, FestGdalRaster*, char*, size_t) = nullptr;
  void (*free_raster)(FestGdalRaster*) = nullptr;
};

// The plugin's entry points. Throws Status::io (exit 4) when the plugin or GDAL itself
// cannot be loaded, naming the Debian package to install (formats/plugin_loader.hpp
// says where the plugin is looked for).
const GdalPlugin& gdal_plugin();

// RAII for a raster the plugin fills; made from the loaded plugin, so that the
// destructor cannot fail.
struct GdalRasterHolder {
  explicit GdalRasterHolder(const GdalPlugin& plugin) : free_raster(plugin.free_raster) {}
  ~GdalRasterHolder() { free_raster(&raster); }
  GdalRasterHolder(const GdalRasterHolder&) = delete;
  GdalRasterHolder& operator=(const GdalRasterHolder&) = delete;
  FestGdalRaster raster{};
  void (*free_raster)(FestGdalRaster*);
};

}  // namespace fest::formats::dem_detail

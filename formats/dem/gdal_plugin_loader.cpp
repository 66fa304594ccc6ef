#include "formats/dem/gdal_plugin_loader.hpp"

#include "core/error.hpp"
#include "formats/plugin_loader.hpp"

namespace fest::formats::dem_detail {

const GdalPlugin& gdal_plugin() {
  // Debian 12's GDAL runtime: a plugin that does not load almost always means a missing
  // libgdal (the plugin itself ships with fest).
  static constexpr PluginModule kModule{"libfest_gdal_plugin.so", "fest_gdal_plugin_table", "GDAL raster support",
                                        "libgdal32"};
  const FestGdalPluginTable* table = plugin_table<FestGdalPluginTable>(kModule);
  if (table->abi != FEST_GDAL_PLUGIN_ABI)
    throw io_error("GDAL raster support is not available (libfest_gdal_plugin.so is from another fest version)");
  static const GdalPlugin plugin{table->open_raster, table->free_raster};
  return plugin;
}

}  // namespace fest::formats::dem_detail

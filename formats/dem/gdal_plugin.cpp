// fest's GDAL plugin: the only code that calls GDAL, built as a shared module that
// formats/dem opens with dlopen when an input needs it (gdal_plugin_api.h says why).
// It reports errors in its C interface and never prints: GDAL's messages are captured
// by a quiet handler and the last one becomes the message.
#include "formats/dem/gdal_plugin_api.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>

namespace {

struct QuietGdal {
  QuietGdal() {
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  static const char* last(const char* fallback) {
    const char* m = CPLGetLastErrorMsg();
    return (m && *m) ? m : fallback;
  }
};

int fail(int code, char* message, std::size_t size, const char* text) {
  std::snprintf(message, size, "%s", text);
  // One line: GDAL's messages sometimes hold newlines.
  for (char* c = message; *c; ++c)
    if (*c == '\n' || *c == '\r') *c = ' ';
  return code;
}

}  // namespace


extern "C" int fest_gdal_open_raster(const char* path, const void* bytes, size_t size, size_t max_values,
                                     FestGdalRaster* out, char* message, size_t message_size) {
  std::memset(out, 0, sizeof *out);
  QuietGdal quiet;
  static std::atomic<int> counter{0};
  std::string name = path ? path : "";
  std::string mem_name;
  if (!path) {
    mem_name = "/vsimem/fest_raster_" + std::to_string(counter++);
    VSILFILE* mem = VSIFileFromMemBuffer(mem_name.c_str(), static_cast<GByte*>(const_cast<void*>(bytes)),
                                         static_cast<vsi_l_offset>(size), FALSE);
    if (!mem) return fail(FEST_GDAL_NO_MEMORY, message, message_size, "cannot buffer standard input for GDAL");
    VSIFCloseL(mem);
    name = mem_name;
  }
  GDALDatasetH ds = GDALOpenEx(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  int rc = 0;
  if (!ds) {
    rc = fail(FEST_GDAL_CANNOT_OPEN, message, message_size, QuietGdal::last("unrecognised format"));
  } else {
    std::snprintf(out->driver, sizeof out->driver, "%s", GDALGetDriverShortName(GDALGetDatasetDriver(ds)));
    out->width = GDALGetRasterXSize(ds);
    out->height = GDALGetRasterYSize(ds);
    out->bands = GDALGetRasterCount(ds);
    out->has_geotransform = GDALGetGeoTransform(ds, out->geotransform) == CE_None;
    const char* wkt = GDALGetProjectionRef(ds);
    if (wkt && *wkt) out->crs = strdup(wkt);
    if (out->bands >= 1) {
      GDALRasterBandH band = GDALGetRasterBand(ds, 1);
      const GDALDataType type = GDALGetRasterDataType(band);
      out->complex_samples = GDALDataTypeIsComplex(type) != 0;
      out->integer = GDALDataTypeIsInteger(type) != 0;
      out->nodata = GDALGetRasterNoDataValue(band, &out->has_nodata);
      const std::size_t n = std::size_t(out->width > 0 ? out->width : 0) * std::size_t(out->height > 0 ? out->height : 0);
      if (n > 0 && n <= max_values && !out->complex_samples) {
        out->values = static_cast<double*>(std::malloc(n * sizeof(double)));
        if (!out->values) rc = fail(FEST_GDAL_NO_MEMORY, message, message_size, "out of memory for the raster's samples");
        else if (GDALRasterIO(band, GF_Read, 0, 0, out->width, out->height, out->values, out->width, out->height,
                              GDT_Float64, 0, 0) != CE_None)
          rc = fail(FEST_GDAL_CANNOT_READ, message, message_size, QuietGdal::last("read error"));
      }
    }
    GDALClose(ds);
  }
  if (!mem_name.empty()) VSIUnlink(mem_name.c_str());
  if (rc) fest_gdal_free_raster(out);
  return rc;
}

extern "C" void fest_gdal_free_raster(FestGdalRaster* raster) {
  std::free(raster->values);
  std::free(raster->crs);
  raster->values = nullptr;
  raster->crs = nullptr;
}

extern "C" __attribute__((visibility("default"))) const FestGdalPluginTable* fest_gdal_plugin_table(void) {
  static const FestGdalPluginTable table{FEST_GDAL_PLUGIN_ABI, &fest_gdal_open_raster, &fest_gdal_free_raster};
  return &table;
}

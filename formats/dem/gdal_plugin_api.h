/* The C interface of fest's GDAL plugin (libfest_gdal_plugin.so), opened with dlopen by
 * formats/dem only when an input is a raster that fest does not read itself, so that
 * tools never map GDAL's ~110 shared libraries for PGM, PNG, PFM or .npy inputs (a
 * tool's start-up is paid once per file in batch runs). Plain C types only: the plugin
 * and the tools need
 * no common C++ ABI. */
#ifndef FEST_GDAL_PLUGIN_API_H
#define FEST_GDAL_PLUGIN_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FEST_GDAL_PLUGIN_ABI 1

typedef struct FestGdalRaster {
  int width, height;
  int bands;
  int integer;            /* samples are integers in the file */
  int complex_samples;
  int has_geotransform;
  double geotransform[6]; /* GDAL's affine transform */
  int has_nodata;
  double nodata;
  char driver[64];        /* GDAL driver short name: "GTiff", "AAIGrid", ... */
  char* crs;              /* WKT (malloc'd, may be NULL) */
  double* values;         /* width * height samples of band 1, row-major (malloc'd);
                             NULL when only the header was asked for */
} FestGdalRaster;

enum {
  FEST_GDAL_OK = 0,
  FEST_GDAL_CANNOT_OPEN = 1,  /* GDAL does not recognise or cannot parse the file */
  FEST_GDAL_CANNOT_READ = 2,  /* opened, but reading band 1 failed */
  FEST_GDAL_NO_MEMORY = 3
};

/* Returns FEST_GDAL_OK, or an error code with GDAL's last message (one line) in
 * `message`. `path` is a file name, or NULL to read `bytes` (standard input) through
 * /vsimem/. Band 1's samples are read when width * height <= max_values (0: header
 * only); otherwise `values` stays NULL. */
int fest_gdal_open_raster(const char* path, const void* bytes, size_t size, size_t max_values,
                          FestGdalRaster* out, char* message, size_t message_size);
void fest_gdal_free_raster(FestGdalRaster* raster);

/* The one symbol the loader looks up (formats/plugin_loader.hpp). */
typedef struct FestGdalPluginTable {
  int abi; /* FEST_GDAL_PLUGIN_ABI of the plugin's build */
  int (*open_raster)(const char*, const void*, size_t, size_t, FestGdalRaster*, char*, size_t);
  void (*free_raster)(FestGdalRaster*);
} FestGdalPluginTable;
const FestGdalPluginTable* fest_gdal_plugin_table(void);

#ifdef __cplusplus
}
#endif

#endif

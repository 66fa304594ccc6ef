#pragma once
// Digital elevation models: every single-band raster GDAL reads (GeoTIFF with its
// georeference, nodata value and CRS, ESRI ASCII grids, 16-bit PNG/PGM, ...) plus the two
// plain formats GDAL lacks, NumPy .npy and PFM, recognised by content.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats {

struct DemRaster {
  int width = 0;   // columns
  int height = 0;  // rows
  std::vector<double> values;  // row-major, row 0 = north; NaN where the file says nodata
  std::string format;          // "npy", "pfm" or the GDAL driver ("GTiff", "AAIGrid", "PNG", ...)
  bool integer = false;        // samples are integers in the file (int16 DEMs)
  // Georeference, when the file has one: centre of the south-west sample and the
  // sample spacing (positive; north-up rasters only).
  bool georeferenced = false;
  double origin_x = 0, origin_y = 0;
  double dx = 1, dy = 1;
  std::string crs;                       // WKT, empty when unknown
  std::optional<double> nodata;          // the file's nodata value
  std::size_t nodata_count = 0;          // samples equal to it (now NaN)
  std::size_t nan_count = 0;             // NaN samples the file did not declare as nodata
};

// Reads a DEM from a file or standard input ("-"). `nodata` (from --nodata) overrides the
// file's nodata value. Throws Status::io when the file cannot be read and
// Status::bad_input for anything malformed (empty, truncated, several bands, rotated
// georeference, an unknown format); messages name `path`.
DemRaster read_dem(const std::string& path, std::optional<double> nodata = std::nullopt);

// The georeference of any raster GDAL opens, whatever its bands (an orthophoto to drape
// over a DEM): same convention as DemRaster (centre of the south-west pixel, positive
// spacing); `georeferenced` false when the file (or its world file) has none. Throws
// Status::io when the file cannot be read, Status::bad_input for what GDAL cannot open and
// for rotated or flipped georeferences.
struct RasterGeoreference {
  bool georeferenced = false;
  int width = 0, height = 0;
  double origin_x = 0, origin_y = 0;
  double dx = 1, dy = 1;
};
RasterGeoreference read_georeference(const std::string& path);

// The .npy reader on its own (tests): little-endian or byte-order-free integers
// (u1, i1, i2, u2, i4, u4) and floats (f4, f8), C order, two dimensions.
DemRaster read_npy(std::string_view bytes);

}  // namespace fest::formats

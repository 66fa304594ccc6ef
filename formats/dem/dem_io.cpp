// DEM reading: .npy, PFM and PGM by fest's own readers, everything else through GDAL,
// which lives in a plugin loaded with dlopen only then (gdal_plugin_loader.hpp): a tool
// reading a PGM or .npy DEM never maps GDAL. Files are opened by path (so GDAL finds
// sidecars such as .tfw world files); standard input goes through a /vsimem/ buffer.

#include "formats/dem/dem_io.hpp"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/dem/gdal_plugin_loader.hpp"
#include "formats/image/image_io.hpp"

namespace fest::formats {
namespace {

// PFM and PGM (plain P2 and raw P5, 8 or 16 bit; GDAL reads only raw PNM) through fest's
// image readers.
DemRaster read_image_dem(std::string_view bytes, Format format) {
  const Image img = read_image(bytes, format);
  if (img.pixels.channels() != 1)
    throw bad_input("{} DEM has {} channels; a single-channel image is needed", format_name(format), img.pixels.channels());
  DemRaster r;
  // PNG keeps the name GDAL's driver gave it before fest read PNG DEMs itself.
  r.format = format == Format::png ? std::string("PNG") : std::string(format_name(format));
  r.integer = format != Format::pfm;
  cv::Mat values;
  img.pixels.convertTo(values, CV_32F);
  r.width = img.pixels.cols;
  r.height = img.pixels.rows;
  r.values.reserve(static_cast<std::size_t>(r.width) * r.height);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) r.values.push_back(values.at<float>(y, x));
  return r;
}

// A PNG whose georeference could only come from a sidecar GDAL reads (world file,
// .aux.xml) goes to GDAL; any other PNG is read by fest, without loading GDAL.
bool png_without_sidecar(const std::string& path, std::string_view bytes) {
  if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return false;
  if (is_stdio(path)) return true;
  const auto dot = path.rfind('.');
  const std::string stem = dot == std::string::npos || path.find('/', dot) != std::string::npos ? path : path.substr(0, dot);
  for (const std::string& sidecar : {stem + ".pgw", stem + ".pngw", stem + ".wld", path + ".aux.xml", stem + ".PGW"})
    if (::access(sidecar.c_str(), F_OK) == 0) return false;
  return true;
}

using dem_detail::gdal_plugin;
using dem_detail::GdalRasterHolder;

// Opens `path` (or `bytes`, for standard input) through the plugin and reads up to
// `max_values` samples of band 1; GDAL's failures are bad input.
void open_with_gdal(const std::string& path, const std::string& bytes, std::size_t max_values, GdalRasterHolder& held,
                    const char* what) {
  char message[512] = {};
  const bool stdio = is_stdio(path);
  const int rc = gdal_plugin().open_raster(stdio ? nullptr : path.c_str(), bytes.data(), bytes.size(), max_values,
                                           &held.raster, message, sizeof message);
  if (rc == FEST_GDAL_CANNOT_OPEN) throw bad_input("{}: {}", what, message);
  if (rc == FEST_GDAL_CANNOT_READ) throw bad_input("cannot read the DEM's samples: {}", message);
  if (rc != FEST_GDAL_OK) throw runtime_failure("GDAL: {}", message);
}

// GDAL's ESRI ASCII grid driver reads a non-numeric or missing value of an integer grid
// as 0, and "nan" as 0 too, without a word: check the samples' text ourselves. A "nan"
// token becomes a NaN sample (an error later unless NaN is the nodata value); anything
// that is not a number, an infinity, or too few values are bad input.
void check_ascii_grid_samples(std::string_view text, DemRaster& r) {
  std::size_t at = 0;
  auto next_token = [&](std::string_view& token) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    const std::size_t begin = at;
    while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    token = text.substr(begin, at - begin);
    return !token.empty();
  };
  auto is_header_key = [](std::string_view t) {
    std::string k(t);
    for (char& c : k) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return k == "ncols" || k == "nrows" || k == "xllcorner" || k == "yllcorner" || k == "xllcenter" || k == "yllcenter" ||
           k == "cellsize" || k == "dx" || k == "dy" || k == "nodata_value";
  };
  std::string_view token;
  std::size_t before = 0;
  for (;;) {  // header: key value pairs
    before = at;
    if (!next_token(token)) break;
    if (!is_header_key(token)) {
      at = before;
      break;
    }
    next_token(token);
  }
  const std::size_t count = r.values.size();
  for (std::size_t k = 0; k < count; ++k) {
    const int row = static_cast<int>(k / static_cast<std::size_t>(r.width)) + 1, column = static_cast<int>(k % static_cast<std::size_t>(r.width)) + 1;
    if (!next_token(token))
      throw bad_input("ESRI ASCII grid has {} of its {} x {} values (the first missing is row {}, column {})", k, r.width,
                      r.height, row, column);
    const std::string value(token);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end != value.c_str() + value.size())
      throw bad_input("ESRI ASCII grid has a non-numeric value '{}' at row {}, column {}", value, row, column);
    if (std::isinf(v)) throw bad_input("ESRI ASCII grid has an infinite value at row {}, column {}", row, column);
    if (std::isnan(v)) r.values[k] = v;
  }
}

DemRaster read_gdal(const std::string& path, const std::string& bytes) {
  // The plugin reads the samples only up to the limit below, checked here for the message.
  const double limit = (8.0 * static_cast<double>(max_input_bytes()) + 1e9) / sizeof(double);
  GdalRasterHolder held(gdal_plugin());
  open_with_gdal(path, bytes, static_cast<std::size_t>(limit), held, "not a DEM that GDAL can read");
  const FestGdalRaster& h = held.raster;
  DemRaster r;
  r.format = h.driver;
  r.width = h.width;
  r.height = h.height;
  if (h.bands != 1) throw bad_input("DEM has {} bands; a single-band raster is needed", h.bands);
  if (r.width <= 0 || r.height <= 0) throw bad_input("DEM has no samples");
  const double samples = static_cast<double>(r.width) * r.height;
  if (samples * sizeof(double) > 8.0 * static_cast<double>(max_input_bytes()) + 1e9)
    throw bad_input("DEM of {} x {} samples is larger than fest accepts", r.width, r.height);
  if (h.complex_samples) throw bad_input("DEM has complex samples");
  r.integer = h.integer != 0;
  if (h.has_nodata) r.nodata = h.nodata;

  if (h.has_geotransform) {
    const double* gt = h.geotransform;
    if (gt[2] != 0 || gt[4] != 0) throw bad_input("DEM georeference is rotated; north-up rasters only");
    if (gt[1] == 0 || gt[5] == 0) throw bad_input("DEM georeference has a zero pixel size");
    r.georeferenced = true;
    r.dx = std::abs(gt[1]);
    r.dy = std::abs(gt[5]);
    // Pixel-is-area: the sample is the centre of its pixel. Row H-1 is the southern one
    // for north-up rasters (gt[5] < 0).
    r.origin_x = gt[0] + 0.5 * gt[1];
    r.origin_y = gt[5] < 0 ? gt[3] + (r.height - 0.5) * gt[5] : gt[3] + 0.5 * gt[5];
    if (gt[5] > 0) throw bad_input("DEM rows run south to north; north-up rasters only");
    if (gt[1] < 0) throw bad_input("DEM columns run east to west; north-up rasters only");
  }
  if (h.crs) r.crs = h.crs;

  if (!h.values) throw bad_input("cannot read the DEM's samples");
  r.values.assign(h.values, h.values + std::size_t(r.width) * std::size_t(r.height));
  if (r.format == "AAIGrid") check_ascii_grid_samples(bytes, r);
  return r;
}

}  // namespace

RasterGeoreference read_georeference(const std::string& path) {
  const std::string bytes = read_input(path);  // the usual I/O errors (missing, unreadable) before GDAL's own
  GdalRasterHolder held(gdal_plugin());
  try {
    open_with_gdal(path, bytes, 0, held, "not a raster that GDAL can read");
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), path));
  }
  RasterGeoreference g;
  g.width = held.raster.width;
  g.height = held.raster.height;
  if (!held.raster.has_geotransform) return g;
  const double* gt = held.raster.geotransform;
  if (gt[2] != 0 || gt[4] != 0) throw bad_input("georeference is rotated; north-up rasters only ({})", path);
  if (gt[1] <= 0 || gt[5] >= 0) throw bad_input("georeference is not north-up with columns running east ({})", path);
  g.georeferenced = true;
  g.dx = gt[1];
  g.dy = -gt[5];
  g.origin_x = gt[0] + 0.5 * gt[1];
  g.origin_y = gt[3] + (g.height - 0.5) * gt[5];
  return g;
}

DemRaster read_dem(const std::string& path, std::optional<double> nodata) {
  const std::string bytes = read_input(path);
  auto where = [&](const Error& e) { return Error(e.status(), with_location(e.what(), is_stdio(path) ? "-" : path)); };
  DemRaster r;
  try {
    if (bytes.empty()) throw bad_input("empty file");
    if (bytes.size() >= 6 && bytes.compare(0, 6, "\x93NUMPY") == 0) r = read_npy(bytes);
    else if (bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == 'f' || bytes[1] == 'F') &&
             (bytes[2] == '\n' || bytes[2] == '\r' || bytes[2] == ' '))
      r = read_image_dem(bytes, Format::pfm);
    else if (bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5') &&
             std::isspace(static_cast<unsigned char>(bytes[2])))
      r = read_image_dem(bytes, Format::pgm);
    else if (png_without_sidecar(path, bytes)) r = read_image_dem(bytes, Format::png);
    else r = read_gdal(path, bytes);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw where(e);
  }
  if (nodata) r.nodata = nodata;
  for (double& v : r.values) {
    if (std::isnan(v)) {
      if (r.nodata && std::isnan(*r.nodata)) ++r.nodata_count;
      else ++r.nan_count;
    } else if (r.nodata && v == *r.nodata) {
      v = std::nan("");
      ++r.nodata_count;
    }
  }
  return r;
}

}  // namespace fest::formats

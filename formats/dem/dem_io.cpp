// DEM reading: .npy and PFM by fest's own readers, everything else through GDAL.
// Files are opened by path (so GDAL finds sidecars such as .tfw world files); standard
// input goes through a /vsimem/ buffer.

#include "formats/dem/dem_io.hpp"

#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
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
  r.format = format_name(format);
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

// GDAL reports problems through a global handler; keep them off stderr and use the last
// message in our own one-line error.
struct QuietGdal {
  QuietGdal() {
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  static std::string last(const char* fallback) {
    const char* m = CPLGetLastErrorMsg();
    return (m && *m) ? std::string(m) : std::string(fallback);
  }
};

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
  QuietGdal quiet;
  static std::atomic<int> counter{0};
  std::string name = path;
  VSILFILE* mem = nullptr;
  if (is_stdio(path)) {
    name = "/vsimem/fest_terrainlod_dem_" + std::to_string(counter++);
    mem = VSIFileFromMemBuffer(name.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                               static_cast<vsi_l_offset>(bytes.size()), FALSE);
    if (mem) VSIFCloseL(mem);
  }
  struct Cleanup {
    GDALDatasetH ds = nullptr;
    std::string mem_name;
    ~Cleanup() {
      if (ds) GDALClose(ds);
      if (!mem_name.empty()) VSIUnlink(mem_name.c_str());
    }
  } cleanup;
  if (mem) cleanup.mem_name = name;
  cleanup.ds = GDALOpenEx(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (!cleanup.ds) throw bad_input("not a DEM that GDAL can read: {}", QuietGdal::last("unrecognised format"));
  GDALDatasetH ds = cleanup.ds;

  DemRaster r;
  r.format = GDALGetDriverShortName(GDALGetDatasetDriver(ds));
  r.width = GDALGetRasterXSize(ds);
  r.height = GDALGetRasterYSize(ds);
  const int bands = GDALGetRasterCount(ds);
  if (bands != 1) throw bad_input("DEM has {} bands; a single-band raster is needed", bands);
  if (r.width <= 0 || r.height <= 0) throw bad_input("DEM has no samples");
  const double samples = static_cast<double>(r.width) * r.height;
  if (samples * sizeof(double) > 8.0 * static_cast<double>(max_input_bytes()) + 1e9)
    throw bad_input("DEM of {} x {} samples is larger than fest accepts", r.width, r.height);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  const GDALDataType type = GDALGetRasterDataType(band);
  if (GDALDataTypeIsComplex(type)) throw bad_input("DEM has complex samples");
  r.integer = GDALDataTypeIsInteger(type) != 0;
  int has_nodata = 0;
  const double nd = GDALGetRasterNoDataValue(band, &has_nodata);
  if (has_nodata) r.nodata = nd;

  double gt[6];
  if (GDALGetGeoTransform(ds, gt) == CE_None) {
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
  const char* wkt = GDALGetProjectionRef(ds);
  if (wkt) r.crs = wkt;

  r.values.resize(static_cast<std::size_t>(r.width) * r.height);
  if (GDALRasterIO(band, GF_Read, 0, 0, r.width, r.height, r.values.data(), r.width, r.height, GDT_Float64, 0, 0) !=
      CE_None)
    throw bad_input("cannot read the DEM's samples: {}", QuietGdal::last("read error"));
  if (r.format == "AAIGrid") check_ascii_grid_samples(bytes, r);
  return r;
}

}  // namespace

RasterGeoreference read_georeference(const std::string& path) {
  read_input(path);  // the usual I/O errors (missing, unreadable) before GDAL's own
  QuietGdal quiet;
  GDALDatasetH ds = GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (!ds) throw bad_input("not a raster that GDAL can read: {} ({})", QuietGdal::last("unrecognised format"), path);
  RasterGeoreference g;
  g.width = GDALGetRasterXSize(ds);
  g.height = GDALGetRasterYSize(ds);
  double gt[6];
  const bool has = GDALGetGeoTransform(ds, gt) == CE_None;
  GDALClose(ds);
  if (!has) return g;
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

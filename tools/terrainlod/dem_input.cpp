#include "dem_input.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"

namespace fest::terrainlod_tool {
namespace {

// "2,3" for messages that quote what was given.
std::string joined(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ",") + fmt::format("{}", v);
  return out;
}

bool all_finite(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

terrainlod::DiagonalRule diagonal_rule(const std::string& name) {
  if (name == "short") return terrainlod::DiagonalRule::shortest;
  if (name == "alternate") return terrainlod::DiagonalRule::alternate;
  if (name == "ne") return terrainlod::DiagonalRule::ne;
  throw usage_error("--diagonal must be short, alternate or ne (got '{}')", name);
}

const char* diagonal_name(terrainlod::DiagonalRule d) {
  switch (d) {
    case terrainlod::DiagonalRule::alternate: return "alternate";
    case terrainlod::DiagonalRule::ne: return "ne";
    default: return "short";
  }
}

void parse_nodata(const std::vector<std::string>& words, DemArgs& dem) {
  bool mode_given = false, value_given = false;
  for (const std::string& w : words) {
    if (w == "fill" || w == "hole") {
      if (mode_given) throw usage_error("--nodata takes one of fill or hole (got both '{}' and another)", w);
      mode_given = true;
      dem.nodata_mode = w == "hole" ? NodataMode::hole : NodataMode::fill;
      continue;
    }
    char* end = nullptr;
    const double v = w.empty() ? 0.0 : std::strtod(w.c_str(), &end);
    const bool number = !w.empty() && end == w.c_str() + w.size() && (std::isfinite(v) || w == "nan" || w == "NaN" || w == "NAN");
    if (!number) throw usage_error("--nodata expects fill, hole, a nodata value or nan (got '{}')", w);
    if (value_given) throw usage_error("--nodata takes one nodata value (got a second, '{}')", w);
    value_given = true;
    dem.nodata = v;
  }
}

const char* nodata_mode_name(NodataMode m) { return m == NodataMode::hole ? "hole" : "fill"; }

const char* start_name(terrainlod::StartRule s) { return s == terrainlod::StartRule::lattice ? "lattice" : "rtin"; }

const char* reference_name(terrainlod::Reference r) {
  switch (r) {
    case terrainlod::Reference::original: return "original";
    case terrainlod::Reference::level_plus_1: return "l+1";
    default: return "l+2";
  }
}

const char* coding_name(Coding c) { return c == Coding::progressive ? "progressive" : "standalone"; }

LoadedDem load_dem(const DemArgs& args) {
  LoadedDem d;
  d.name = is_stdio(args.path) ? "-" : args.path;
  std::optional<double> nodata;
  bool nan_is_nodata = false;
  if (args.nodata) {
    if (std::isnan(*args.nodata)) nan_is_nodata = true;
    else nodata = *args.nodata;
  }
  // Flags are checked before the (possibly large) DEM is read.
  const std::vector<double>& cell = args.cell_size;
  const std::vector<double>& origin = args.origin;
  if (!cell.empty() && (cell.size() > 2 || !all_finite(cell) || cell[0] <= 0 || cell.back() <= 0))
    throw usage_error("--cell-size expects dx or dx,dy, both positive (got '{}')", joined(cell));
  if (!origin.empty() && (origin.size() != 2 || !all_finite(origin)))
    throw usage_error("--origin expects x0,y0 (got '{}')", joined(origin));
  if (!std::isfinite(args.z_scale) || args.z_scale == 0 || !std::isfinite(args.z_offset))
    throw usage_error("--z-scale must be finite and non-zero, --z-offset finite");

  d.raster = formats::read_dem(args.path, nodata);
  auto& r = d.raster;
  if (r.nan_count > 0 && !nan_is_nodata)
    throw bad_input("DEM has {} NaN height{}; pass --nodata nan to treat them as nodata ({})", r.nan_count,
                    r.nan_count == 1 ? "" : "s", d.name);
  d.dx = r.dx, d.dy = r.dy, d.origin_x = r.origin_x, d.origin_y = r.origin_y;
  if (!cell.empty()) d.dx = cell[0], d.dy = cell.back();
  if (!origin.empty()) d.origin_x = origin[0], d.origin_y = origin[1];

  // Rows arrive north first; the grid counts rows from the south.
  d.grid.width = r.width;
  d.grid.height = r.height;
  d.grid.h.resize(static_cast<std::size_t>(r.width) * r.height);
  for (int row = 0; row < r.height; ++row)
    for (int i = 0; i < r.width; ++i) {
      const double v = r.values[static_cast<std::size_t>(row) * r.width + i];
      d.grid.h[static_cast<std::size_t>(r.height - 1 - row) * r.width + i] = v * args.z_scale + args.z_offset;
    }
  r.values.clear();
  r.values.shrink_to_fit();
  try {
    d.condition = terrainlod::condition_grid(d.grid);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), d.name));
  }
  return d;
}

nlohmann::json dem_json(const LoadedDem& dem) {
  const auto& r = dem.raster;
  nlohmann::json j = {{"format", r.format},
                      {"width", r.width},
                      {"height", r.height},
                      {"integer", r.integer},
                      {"georeferenced", r.georeferenced},
                      {"origin", {dem.origin_x, dem.origin_y}},
                      {"cell_size", {dem.dx, dem.dy}},
                      {"nodata_samples", dem.condition.nodata},
                      {"z_min", dem.condition.z_min},
                      {"z_max", dem.condition.z_max}};
  j["nodata_value"] = r.nodata && std::isfinite(*r.nodata) ? nlohmann::json(*r.nodata) : nlohmann::json(nullptr);
  j["crs"] = r.crs.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.crs);
  return j;
}

}  // namespace fest::terrainlod_tool

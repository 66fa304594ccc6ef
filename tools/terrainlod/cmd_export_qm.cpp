// terrainlod export-qm: Cesium quantized-mesh-1.0 tiles (base triangulations) and layer.json,
// written into a temporary directory renamed into place when complete.

#include "commands.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "pyramid_view.hpp"
#include "terrainlod/quantized_mesh.hpp"

namespace fest::terrainlod_tool {

int run_export_qm(const ExportQmArgs& args) {
  namespace fs = std::filesystem;
  if (args.output.empty() || is_stdio(args.output)) throw usage_error("export-qm needs -o DIR");
  const fs::path dir = fs::path(args.output).lexically_normal();
  const fs::path target = dir.filename().empty() ? dir.parent_path() : dir;
  std::error_code ec;
  if (fs::exists(target, ec) && !(fs::is_directory(target, ec) && fs::is_empty(target, ec)))
    throw io_error("{} exists and is not an empty directory", target.string());
  PyramidFile pyr = open_pyramid(args.pyramid);
  const auto& L = pyr.layout();
  // Everything goes into a temporary sibling directory, renamed into place when complete.
  const fs::path tmp = target.string() + ".part-" + std::to_string(::getpid());
  fs::remove_all(tmp, ec);
  try {
    Progress bar("terrainlod export-qm", pyr.index().size(), progress_wanted(args.progress));
    for (const auto& e : pyr.index()) {
      bar.advance();
      const auto g = pyr.geometry(e.id.level);
      terrainlod::QmFrame f;
      f.gx0 = static_cast<std::int64_t>(e.id.x) * g.cells;
      f.gy0 = static_cast<std::int64_t>(e.id.y) * g.cells;
      f.cells = g.cells;
      f.origin_x = L.origin_x, f.origin_y = L.origin_y, f.dx = L.dx, f.dy = L.dy;
      terrainlod::TileTriangulation tri = terrainlod::triangulate(pyr.tile(e.id), 0, g);
      if (pyr.nodata()) terrainlod::cut_holes(*pyr.nodata(), tri);  // --nodata hole: as extract draws it
      const std::string qm = terrainlod::encode_quantized_mesh(tri, f);
      const fs::path file = tmp / std::to_string(e.id.level) / std::to_string(e.id.x) / (std::to_string(e.id.y) + ".terrain");
      fs::create_directories(file.parent_path());
      std::ofstream out(file, std::ios::binary);
      out.write(qm.data(), static_cast<std::streamsize>(qm.size()));
      if (!out) throw io_error("cannot write {}", file.string());
    }
    bar.finish();
    nlohmann::json available = nlohmann::json::array();
    for (int l = 0; l <= L.levels; ++l)
      available.push_back({{{"startX", 0}, {"startY", 0}, {"endX", L.tiles_x[static_cast<std::size_t>(l)] - 1},
                            {"endY", L.tiles_y[static_cast<std::size_t>(l)] - 1}}});
    const nlohmann::json layer = {{"tilejson", "2.1.0"},       {"name", "terrainlod"},
                                  {"format", "quantized-mesh-1.0"}, {"version", "1.0.0"},
                                  {"scheme", "tms"},           {"tiles", {"{z}/{x}/{y}.terrain"}},
                                  {"minzoom", 0},              {"maxzoom", L.levels},
                                  {"available", available},    {"projection", "the DEM's own (not EPSG:4326)"}};
    std::ofstream lj(tmp / "layer.json");
    lj << layer.dump(2) << "\n";
    if (!lj) throw io_error("cannot write {}", (tmp / "layer.json").string());
    lj.close();
    if (fs::exists(target, ec)) fs::remove(target, ec);
    fs::rename(tmp, target, ec);
    if (ec) throw io_error("cannot rename {} to {}: {}", tmp.string(), target.string(), ec.message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  return 0;
}

}  // namespace fest::terrainlod_tool

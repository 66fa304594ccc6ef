// isosurf stats MESH: topology, area and volume of any mesh (docs/isosurf.md "Stats").
#include <cstdio>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "isosurface/mesh_stats.hpp"
#include "surface_io.hpp"

namespace fest::isosurf_tool {

int run_stats(const StatsOptions& o) {
  std::size_t fanned = 0;
  const auto s = decode_surface(o.input, fanned);
  auto j = stats_json(isosurface::mesh_stats(s));
  j["polygons_fanned"] = fanned;
  const std::string text = j.dump(2) + "\n";
  if (!o.report.empty()) write_output(o.report, text);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace fest::isosurf_tool

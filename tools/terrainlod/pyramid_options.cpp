#include "pyramid_options.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "terrainlod/pyramid_plan.hpp"

namespace fest::terrainlod_tool {

void check_tile_options(int tile, int texels, double error_fraction) {
  if (!terrainlod::is_power_of_two(tile) || tile < 4 || tile > 4096)
    throw usage_error("--tile must be a power of two between 4 and 4096 (got {})", tile);
  const int t = texels == 0 ? tile : texels;
  if (!terrainlod::is_power_of_two(t) || t > 65536) throw usage_error("--texels must be a power of two (got {})", t);
  if (t < tile) throw usage_error("--texels ({}) must be at least --tile ({})", t, tile);
  if (!(error_fraction > 0) || !std::isfinite(error_fraction))
    throw usage_error("--error-fraction must be a positive number (got {})", error_fraction);
}

void check_quantum_options(double height_quantum, double leaf_error) {
  if (!(height_quantum > 0) || !(height_quantum <= 1))
    throw usage_error("--height-quantum must be in (0, 1] (got {})", height_quantum);
  if (!(leaf_error >= 0) || !std::isfinite(leaf_error))
    throw usage_error("--leaf-error must be a finite number >= 0 (got {})", leaf_error);
}

terrainlod::TileId parse_tile(const std::string& s) {
  terrainlod::TileId id;
  char a = 0, b = 0;
  std::istringstream in(s);
  if (!(in >> id.level >> a >> id.x >> b >> id.y) || a != '/' || b != '/' || !in.eof() || id.level < 0 || id.x < 0 || id.y < 0)
    throw usage_error("--tile expects L/X/Y (got '{}')", s);
  return id;
}

formats::OutputFormat mesh_output(const std::string& path, const std::optional<formats::OutputFormat>& to) {
  formats::OutputFormat out = to ? *to
                              : is_stdio(path) ? formats::OutputFormat{formats::Format::ply, false}
                                               : formats::output_format_from_path(path);
  if (formats::kind_of(out.format) != formats::Kind::mesh)
    throw usage_error("output must be a mesh format (ply, obj, off, stl, drc), not {}", formats::format_name(out.format));
  return out;
}

}  // namespace fest::terrainlod_tool

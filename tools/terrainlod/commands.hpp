#pragma once
// terrainlod subcommands: formats/dem -> lib/terrainlod -> formats/mesh, JSON.

#include <optional>
#include <string>
#include <vector>

#include "formats/detect.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/tile.hpp"

namespace fest::terrainlod_tool {

// How tiles are coded in a pyramid (docs/terrainlod.md, tile coding).
enum class Coding { progressive, standalone };
// How texture tiles are stored.
enum class TextureFormat { png, jpeg };

// What build does with nodata samples (docs/terrainlod.md §5, holes): fill them with the
// nearest valid height (drawn), or fill the geometry alike but store the mask and draw
// no triangle over a nodata sample.
enum class NodataMode { fill, hole };

// The flag spellings of the enums, as reports print them.
const char* diagonal_name(terrainlod::DiagonalRule d);
const char* start_name(terrainlod::StartRule s);
const char* reference_name(terrainlod::Reference r);
const char* coding_name(Coding c);
const char* nodata_mode_name(NodataMode m);
// "L/X/Y" (X east, Y north, from the south-west) -> a tile id; a usage error otherwise.
terrainlod::TileId parse_tile(const std::string& text);
// -o and --to -> the mesh format written (usage error for anything but a mesh format):
// --to, else standard output's PLY, else the file's extension.
formats::OutputFormat mesh_output(const std::string& path, const std::optional<formats::OutputFormat>& to);

// How a DEM file becomes heights on a grid (docs/terrainlod.md).
struct DemArgs {
  std::string path;
  std::vector<double> cell_size;  // {dx} or {dx, dy}; overrides the file's georeference
  std::vector<double> origin;     // {x0, y0}: centre of the south-west sample
  double z_scale = 1, z_offset = 0;
  std::optional<double> nodata;   // overrides the file's; NaN accepts NaN heights as nodata
  NodataMode nodata_mode = NodataMode::fill;  // build: fill or cut holes
  terrainlod::DiagonalRule diagonal = terrainlod::DiagonalRule::shortest;
};

// --nodata's words (each fill, hole, a number or nan; at most one mode and one value)
// -> dem.nodata_mode and dem.nodata; a one-line usage error naming the flag otherwise.
void parse_nodata(const std::vector<std::string>& words, DemArgs& dem);

struct SimplifyArgs {
  DemArgs dem;
  double max_error = -1;
  std::string output = "-";
  std::optional<formats::OutputFormat> to;  // --to; unset = from -o
  std::string report;
  bool quiet = false;
  terrainlod::StartRule start = terrainlod::StartRule::rtin;  // engine start mesh
  bool progress = false;  // --progress: the collapse cost on its way to the bound
};

struct StatsArgs {
  DemArgs dem;
  int tile = 64;
  int texels = 0;
  double error_fraction = 1.0;
  bool progress = false;  // --progress: a pyramid's tiles measured
};

struct BuildArgs {
  DemArgs dem;
  std::string output;
  int tile = 64;
  int texels = 0;
  double error_fraction = 1.0;
  double height_quantum = 0.25;
  double z_quantum = 0;   // 0 = 1 for integer DEMs, else 0.01
  double leaf_error = 0;
  terrainlod::Reference reference = terrainlod::Reference::level_plus_2;
  terrainlod::StartRule start = terrainlod::StartRule::rtin;  // engine start mesh
  Coding coding = Coding::progressive;  // tile coding
  int threads = 0;
  std::string report;
  bool progress = false;
  std::string texture;               // image file, or empty: no image texture
  bool hillshade = false;            // --texture hillshade: textures shaded from the DEM
  std::string texture_mip;           // or a prefiltered pyramid PREFIX_<k>.png (resample mip build)
  TextureFormat texture_format = TextureFormat::png;  // png (lossless) or jpeg
  int texture_quality = 90;          // JPEG quality
};

struct DecodeArgs {
  std::string pyramid;
  terrainlod::TileId tile;
  int mask = 0;
  std::string output = "-";
  std::optional<formats::OutputFormat> to;  // --to; unset = from -o
  std::string texture;    // also write the tile's stored texture image here
};

struct ExtractArgs {
  std::string pyramid;
  std::string camera;     // JSON object
  std::string path;       // JSON lines, one camera per frame
  std::string output = "-";
  std::optional<formats::OutputFormat> to;  // --to; unset = from -o
  double tau = 0;         // 0 = the camera's tau_px (default 1)
  std::string report;
  std::string png;        // software rendering of the mesh, textured or tiles coloured by level
  bool clip = false;      // cut the triangles at the DEM's edges (none of the padding)
  std::string atlas;      // one texture atlas for all drawn tiles (texture coordinates into it)
  std::string camera_preset;  // no --camera: frame the terrain from this side (empty = overview)
  double z_exaggeration = 1;  // heights of the output mesh and rendering multiplied by this
  bool progress = false;      // --progress: tiles decoded, mesh, picture (a path: frames)
};

struct VerifyArgs {
  std::string pyramid;
  DemArgs dem;            // dem.path empty = no error check against the DEM
  int cameras = 20;
  unsigned seed = 1;
  bool progress = false;  // --progress: tiles checked, then cameras
};

struct ExportQmArgs {
  std::string pyramid;
  std::string output;     // directory
  bool progress = false;  // --progress: tiles written
};

int run_export_qm(const ExportQmArgs& args);
int run_simplify(const SimplifyArgs& args);
int run_build(const BuildArgs& args);
int run_decode(const DecodeArgs& args);
int run_extract(const ExtractArgs& args);
int run_verify(const VerifyArgs& args);
// `stats` on a pyramid archive (run_stats hands over when the input is one).
int run_pyramid_stats(const std::string& path, bool progress = false);
int run_stats(const StatsArgs& args);

}  // namespace fest::terrainlod_tool

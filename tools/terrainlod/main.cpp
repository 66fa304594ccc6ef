// terrainlod: multiresolution terrain with a guaranteed vertical error per tile
// (docs/terrainlod.md): simplify, build, decode, extract, verify, stats.
//
// Wiring only: this file maps flags onto commands.hpp.

#include <optional>
#include <utility>
#include <vector>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"
#include "terrainlod/auto_camera.hpp"

namespace {

using namespace fest::terrainlod_tool;
namespace tl = fest::terrainlod;

const std::vector<std::pair<std::string, tl::DiagonalRule>> kDiagonals{
    {"short", tl::DiagonalRule::shortest}, {"alternate", tl::DiagonalRule::alternate}, {"ne", tl::DiagonalRule::ne}};
const std::vector<std::pair<std::string, tl::StartRule>> kStarts{{"rtin", tl::StartRule::rtin}, {"lattice", tl::StartRule::lattice}};
const std::vector<std::pair<std::string, tl::Reference>> kReferences{
    {"l+2", tl::Reference::level_plus_2}, {"l+1", tl::Reference::level_plus_1}, {"original", tl::Reference::original}};
const std::vector<std::pair<std::string, Coding>> kCodings{{"progressive", Coding::progressive}, {"standalone", Coding::standalone}};
const std::vector<std::pair<std::string, TextureFormat>> kTextureFormats{{"png", TextureFormat::png}, {"jpeg", TextureFormat::jpeg}};

// --nodata takes words (fill, hole) and a value (a number or nan), separated by commas or
// given twice; parse_nodata turns them into DemArgs.
CLI::Option* add_nodata_option(CLI::App* cmd, std::vector<std::string>& words, const std::string& help) {
  return cmd->add_option("--nodata", words, help)->delimiter(',')->allow_extra_args(false)->type_name("fill|hole|VALUE|nan");
}

void add_dem_options(CLI::App* cmd, DemArgs& d, std::vector<std::string>& nodata) {
  cmd->add_option("dem", d.path,
                  "DEM: GeoTIFF, ESRI ASCII grid, 16-bit PNG/PGM, .npy, PFM or any raster GDAL reads; - = standard input")
      ->required();
  cmd->add_option("--cell-size", d.cell_size, "Sample spacing dx[,dy] in world units (overrides the file)")->delimiter(',')->allow_extra_args(false);
  cmd->add_option("--origin", d.origin, "x0,y0: world position of the south-west sample (overrides the file)")->delimiter(',')->allow_extra_args(false);
  cmd->add_option("--z-scale", d.z_scale, "Height = value x scale + offset");
  cmd->add_option("--z-offset", d.z_offset, "Height = value x scale + offset");
  add_nodata_option(cmd, nodata,
                    "fill (default): nodata samples take the nearest valid height; hole: build keeps that geometry "
                    "but draws no triangle over a nodata sample. A number: the nodata value (overrides the file's); "
                    "nan accepts NaN heights as nodata. Both: --nodata hole,-9999");
  fest::cli::enum_words(cmd->add_option("--diagonal", d.diagonal, "Finest triangulation: short (3-D shorter diagonal), alternate, ne"), kDiagonals);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Multiresolution terrain from a DEM with a guaranteed vertical error: simplify a DEM to a\n"
               "triangle mesh within a bound; build a crack-free tile pyramid and extract views from it.",
               "terrainlod"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  std::vector<std::string> simplify_nodata, build_nodata, verify_nodata, stats_nodata;
  SimplifyArgs simplify;
  auto* s = app.add_subcommand("simplify", "Simplify the whole DEM to a mesh within --max-error (vertical, exact)");
  add_dem_options(s, simplify.dem, simplify_nodata);
  s->add_option("--max-error", simplify.max_error, "Largest vertical distance from the DEM surface (height units)")
      ->required();
  s->add_option("-o,--output", simplify.output, "Mesh file (.ply .obj .off .stl .drc); - = standard output (PLY)");
  std::string simplify_to, decode_to, extract_to;
  s->add_option("--to", simplify_to, "Output format: ply, obj, off, stl or drc");
  s->add_option("--report", simplify.report, "JSON report: counts, times, the re-measured error");
  fest::cli::enum_words(s->add_option("--start", simplify.start, "What the engine decimates from: rtin (a coarse RTIN within the bound) or lattice (every sample)"), kStarts);
  fest::cli::add_progress(*s, simplify.progress);

  BuildArgs build;
  auto* b = app.add_subcommand("build", "Build the tile pyramid of a DEM (.tlp archive)");
  add_dem_options(b, build.dem, build_nodata);
  b->add_option("-o,--output", build.output, "PYRAMID.tlp archive, or a directory (pyramid.json + L/X/Y.tlt + L/X/Y.png); written atomically")->required();
  std::string texture;  // an image file or the word hillshade
  auto* tex_opt = b->add_option("--texture", texture,
                "Texture image covering the DEM (its edges on the outer samples, or one pixel per sample), or 'hillshade'");
  b->add_option("--texture-mip", build.texture_mip,
                "Prefiltered texture pyramid PREFIX_<k>.png (k = 0 full size, as `resample mip build` writes) instead of --texture")
      ->excludes(tex_opt);
  fest::cli::enum_words(b->add_option("--texture-format", build.texture_format, "Texture tiles: png (lossless) or jpeg"), kTextureFormats);
  b->add_option("--texture-quality", build.texture_quality, "JPEG quality of the texture tiles (1-100)")
      ->check(fest::cli::range(1, 100));
  b->add_option("--tile", build.tile, "Leaf tile size B in DEM cells (power of two, 4..4096)")->check(fest::cli::range(4, 4096));
  b->add_option("--texels", build.texels, "Texels per tile side T (power of two >= B; default B)")->check(fest::cli::range(4, 65536));
  b->add_option("--error-fraction", build.error_fraction, "Allowed error per tile in texels (f)");
  b->add_option("--height-quantum", build.height_quantum, "Interior height quantum as a fraction of eps_l (q)");
  b->add_option("--z-quantum", build.z_quantum, "Finest height quantum (default 1 for integer DEMs, else 0.01)");
  b->add_option("--leaf-error", build.leaf_error, "Tolerance of the leaf level (height units)");
  fest::cli::enum_words(b->add_option("--reference", build.reference,
                "What level l is measured against: l+2 (the seed's, <= 4/3 eps_l), l+1 (<= 2 eps_l) or original (the DEM, eps_l)"), kReferences);
  fest::cli::enum_words(b->add_option("--start", build.start, "What each tile's engine decimates from: rtin (a coarse RTIN within eps_l) or lattice"), kStarts);
  fest::cli::enum_words(b->add_option("--coding", build.coding,
                                      "Tile coding: progressive (a child tile codes only what its parent does not give; "
                                      "decoding needs the parent) or standalone (every tile decodable alone)"),
                        kCodings);
  b->add_option("--report", build.report, "JSON report: tiles, bytes, times, peak memory");
  fest::cli::add_progress(*b, build.progress);
  fest::cli::add_threads(*b, build.threads);

  DecodeArgs decode;
  auto* d = app.add_subcommand("decode", "Decode one tile for a neighbour mask to a mesh");
  d->add_option("pyramid", decode.pyramid, "Pyramid archive (.tlp) or directory")->required();
  std::string decode_tile;
  d->add_option("--tile", decode_tile, "Tile L/X/Y (X east, Y north, from the south-west)")->required();
  d->add_option("--mask", decode.mask, "Neighbour mask 0..15: bit 1 west, 2 south, 4 east, 8 north is one level finer")->check(fest::cli::range(0, 15));
  d->add_option("-o,--output", decode.output, "Mesh file; - = standard output (PLY)");
  d->add_option("--to", decode_to, "Output format: ply, obj, off, stl or drc");
  d->add_option("--texture", decode.texture, "Also write the tile's texture, as stored (PNG or JPEG)");

  ExtractArgs extract;
  auto* x = app.add_subcommand("extract", "The crack-free mesh a camera needs (view-dependent level of detail)");
  x->add_option("pyramid", extract.pyramid, "Pyramid archive (.tlp) or directory")->required();
  fest::cli::add_progress(*x, extract.progress);
  auto* cam_opt = x->add_option("--camera", extract.camera,
                                "Camera JSON: eye, target, up, fovy_deg, width, height, near, far, tau_px "
                                "(default: a 1280 x 800 view framing the whole terrain, --camera-preset)");
  auto* preset_opt = x->add_option("--camera-preset", extract.camera_preset,
                                   "Without --camera, frame the whole terrain from: overview (south-west, 35 deg; the default), "
                                   "oblique (south-west, 20 deg), north, south, east, west (30 deg) or top")
                         ->check(CLI::IsMember(fest::terrainlod::camera_preset_names()));
  preset_opt->excludes(cam_opt);
  auto* path_opt = x->add_option("--path", extract.path,
                                 "Camera path: JSON lines, one camera per frame (-o and --png then take a %d / %04d pattern)");
  cam_opt->excludes(path_opt);
  preset_opt->excludes(path_opt);
  x->add_option("--z-exaggeration", extract.z_exaggeration,
                "Multiply heights of the written mesh and the rendering by K (no rebuild; default 1)")
      ->check(fest::cli::positive);
  path_opt->excludes(cam_opt);
  x->add_option("-o,--output", extract.output, "Mesh file; - = standard output (PLY); faces coloured by tile level");
  x->add_option("--to", extract_to, "Output format: ply, obj, off, stl or drc");
  x->add_option("--tau", extract.tau, "Pixels per texel threshold (overrides the camera's tau_px)");
  x->add_option("--report", extract.report, "JSON report: tiles per level, triangles, bytes touched, times");
  x->add_option("--png", extract.png, "Also render the mesh as the camera sees it (textured, or tiles coloured by level)");
  x->add_flag("--clip", extract.clip, "Cut the triangles at the DEM's edges: exactly the DEM rectangle, none of the pyramid's padding");
  x->add_option("--atlas", extract.atlas, "Pack the drawn tiles' textures into one PNG; texture coordinates point into it");

  VerifyArgs verify;
  auto* v = app.add_subcommand("verify", "Check a pyramid: decoding, the error bound of every transition, cracks");
  v->add_option("pyramid", verify.pyramid, "Pyramid archive (.tlp) or directory")->required();
  v->add_option("--dem", verify.dem.path, "The DEM it was built from: check every triangulation within 4/3 eps");
  v->add_option("--cell-size", verify.dem.cell_size, "As for build")->delimiter(',')->allow_extra_args(false);
  v->add_option("--origin", verify.dem.origin, "As for build")->delimiter(',')->allow_extra_args(false);
  v->add_option("--z-scale", verify.dem.z_scale, "As for build");
  v->add_option("--z-offset", verify.dem.z_offset, "As for build");
  add_nodata_option(v, verify_nodata, "As for build (the holes are the pyramid's: fill or hole changes nothing here)");
  v->add_option("--cameras", verify.cameras, "Random cameras for the crack check")->check(fest::cli::range(0, 1000000));
  v->add_option("--seed", verify.seed, "Seed of the random cameras");
  fest::cli::add_progress(*v, verify.progress);

  ExportQmArgs qm;
  auto* q = app.add_subcommand("export-qm", "Cesium quantized-mesh-1.0 tiles (base triangulations) and layer.json");
  q->add_option("pyramid", qm.pyramid, "Pyramid archive (.tlp) or directory")->required();
  q->add_option("-o,--output", qm.output, "Output directory (new or empty; written completely or not at all)")->required();
  fest::cli::add_progress(*q, qm.progress);

  StatsArgs stats;
  auto* st = app.add_subcommand("stats", "JSON statistics of a pyramid (.tlp), or of a DEM and its pyramid plan");
  add_dem_options(st, stats.dem, stats_nodata);
  st->add_option("--tile", stats.tile, "Leaf tile size B in DEM cells (power of two, 4..4096)")->check(fest::cli::range(4, 4096));
  st->add_option("--texels", stats.texels, "Texels per tile side T (power of two >= B; default B)")->check(fest::cli::range(4, 65536));
  st->add_option("--error-fraction", stats.error_fraction, "Allowed error per tile in texels (f)");
  fest::cli::add_progress(*st, stats.progress);

  return fest::cli::run(app, argc, argv, [&] {
    // Format names become formats when the command runs (usage errors naming the word).
    auto format = [](const std::string& name) {
      return name.empty() ? std::nullopt : std::optional<fest::formats::OutputFormat>(fest::formats::output_format_from_name(name));
    };
    parse_nodata(simplify_nodata, simplify.dem);
    parse_nodata(build_nodata, build.dem);
    parse_nodata(verify_nodata, verify.dem);
    parse_nodata(stats_nodata, stats.dem);
    if (s->parsed()) {
      simplify.to = format(simplify_to);
      return run_simplify(simplify);
    }
    if (b->parsed()) {
      build.hillshade = texture == "hillshade";
      if (!build.hillshade) build.texture = texture;
      return run_build(build);
    }
    if (d->parsed()) {
      decode.tile = parse_tile(decode_tile);
      decode.to = format(decode_to);
      return run_decode(decode);
    }
    if (x->parsed()) {
      extract.to = format(extract_to);
      return run_extract(extract);
    }
    if (v->parsed()) return run_verify(verify);
    if (q->parsed()) return run_export_qm(qm);
    return run_stats(stats);
  });
}

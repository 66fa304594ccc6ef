// terrainlod verify: every tile decodes and re-encodes to its bytes, every transition stays within
// its bound of the DEM, textures decode, random cameras see no cracks.

#include "commands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <set>

#include "core/error.hpp"
#include "core/progress.hpp"
#include "dem_input.hpp"
#include "pyramid_view.hpp"
#include "terrainlod/nodata_mask.hpp"
#include "terrainlod/progressive_recode.hpp"
#include "terrainlod/tile_codec.hpp"
#include "core/json_value.hpp"

namespace fest::terrainlod_tool {

int run_verify(const VerifyArgs& args) {
  if (args.cameras < 0) throw usage_error("--cameras must be >= 0 (got {})", args.cameras);
  PyramidFile pyr = open_pyramid(args.pyramid);
  const auto& L = pyr.layout();
  nlohmann::json j;
  bool ok = true;
  // 1. Every tile decodes, re-encodes to the same bytes, and (with --dem) every one of
  //    its transition triangulations stays within 4/3 eps_l of the DEM.
  std::optional<LoadedDem> dem;
  std::optional<terrainlod::HeightGrid> padded;
  std::optional<terrainlod::ReferenceSurface> ref;
  if (!args.dem.path.empty()) {
    dem = load_dem(args.dem);
    if (dem->grid.width != json_integer<int>(pyr.manifest().at("width")) || dem->grid.height != json_integer<int>(pyr.manifest().at("height")))
      throw bad_input("DEM is {} x {} samples but the pyramid was built from {} x {} ({})", dem->grid.width, dem->grid.height,
                      json_integer<int>(pyr.manifest().at("width")), json_integer<int>(pyr.manifest().at("height")), dem->name);
    padded = terrainlod::pad_grid(dem->grid, json_integer<int>(pyr.manifest().at("padded")));
    ref.emplace(*padded, diagonal_rule(pyr.manifest().value("diagonal", std::string("short"))));
  }
  // The guarantee against the DEM for the reference the pyramid was built with (docs/terrainlod.md §1):
  // eps (1 + 1/4 + ...) = 4/3 eps for level l+2, eps (1 + 1/2 + ...) = 2 eps for l+1.
  const std::string reference = pyr.manifest().value("reference", std::string("l+2"));
  const double factor = reference == "original" ? 1.0 : reference == "l+1" ? 2.0 : 4.0 / 3.0;
  std::size_t triangulations = 0, reencode_mismatch = 0, over = 0;
  double worst_ratio = 0;
  int level_at = -1;
  // One bar: the tiles, their textures, then the cameras; where each part ends as measured
  // on a 2049^2 fBm pyramid (2,700 tiles, 20 cameras): the tiles take a third of the time,
  // more than half when they are measured against the DEM.
  Progress bar("terrainlod verify", 0, progress_wanted(args.progress));
  const double checks_end = args.cameras == 0 ? 1.0 : ref ? 0.55 : 0.33;
  const double tiles_end = pyr.textured() ? 0.9 * checks_end : checks_end;
  const ProgressFn tile_progress = progress_part(bar.callback(), 0.0, tiles_end);
  const ProgressFn texture_progress = progress_part(bar.callback(), tiles_end, checks_end);
  const ProgressFn camera_progress = progress_part(bar.callback(), checks_end, 1.0);
  std::uint64_t tiles_done = 0;
  const std::uint64_t tile_count = pyr.index().size();
  for (const auto& e : pyr.index()) {
    if (tile_progress) tile_progress(tiles_done++, tile_count);
    if (e.id.level != level_at) keep_parents_only(pyr, level_at = e.id.level);
    const auto& t = pyr.tile(e.id);
    // Coding again in the stored coding (same strip order) gives the same bytes.
    const std::string_view stored = pyr.tile_bytes(e.id);
    if (terrainlod::recode_tile(stored, terrainlod::tile_coding(stored), pyr.parent_of(e.id)) != stored) ++reencode_mismatch;
    if (!ref) continue;
    const double eps = pyr.manifest().at("level").at(static_cast<std::size_t>(e.id.level)).at("eps").get<double>();
    const double bound = e.id.level == L.levels ? eps + 0.5 * pyr.geometry(e.id.level).delta_min : factor * eps;
    // All of the tile's triangulations at once (a triangle they share is measured once).
    const terrainlod::TileErrorRange r = terrainlod::tile_error(*ref, t, pyr.geometry(e.id.level));
    triangulations += r.triangulations;
    if (r.err > bound * (1 + 1e-9) + 1e-9) ++over;
    if (eps > 0) worst_ratio = std::max(worst_ratio, r.err / eps);
  }
  j["tiles"] = pyr.index().size();
  j["reencode_mismatches"] = reencode_mismatch;
  ok = ok && reencode_mismatch == 0;
  // Texture tiles: every one decodes to T x T 8-bit pixels.
  if (pyr.textured()) {
    std::size_t bad_textures = 0;
    std::uint64_t textures_done = 0;
    for (const auto& e : pyr.index()) {
      try {
        decode_texture(pyr, e.id);
      } catch (const Error&) {
        ++bad_textures;
      }
      if (texture_progress) texture_progress(++textures_done, tile_count);
    }
    j["bad_textures"] = bad_textures;
    ok = ok && bad_textures == 0;
  } else {
    j["bad_textures"] = nullptr;
  }
  // With --dem, a pyramid with holes must hold the DEM's nodata samples, no more, no fewer.
  if (dem && pyr.nodata()) {
    const bool same = terrainlod::encode_nodata_mask(terrainlod::nodata_mask(dem->grid)) == terrainlod::encode_nodata_mask(*pyr.nodata());
    j["nodata_mask_matches_dem"] = same;
    ok = ok && same;
  }
  if (ref) {
    j["triangulations_checked"] = triangulations;
    j["tiles_over_bound"] = over;
    j["max_err_over_eps"] = worst_ratio;
    j["bound_over_eps"] = factor;
    ok = ok && over == 0;
  } else {
    j["triangulations_checked"] = nullptr;
  }
  // 2. Random cameras: the extracted meshes have no cracks or T-junctions.
  std::mt19937 rng(args.seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double wx = L.cells[0] * L.tiles_x[0] * L.dx, wy = L.cells[0] * L.tiles_y[0] * L.dy;
  double zlo = 0, zhi = 0;
  {
    const auto& root = pyr.tile({0, 0, 0});
    zlo = root.z_min, zhi = root.z_max;
  }
  std::size_t open_total = 0, tiles_total = 0, hole_edges = 0, hole_triangles = 0, drawn_over_nodata = 0;
  const terrainlod::NodataMask* nodata = pyr.nodata();
  std::set<int> levels_seen;
  for (int c = 0; c < args.cameras; ++c) {
    if (camera_progress) camera_progress(static_cast<std::uint64_t>(c), static_cast<std::uint64_t>(args.cameras));
    terrainlod::Camera cam;
    cam.eye = {L.origin_x + u(rng) * wx, L.origin_y + u(rng) * wy, zhi + (0.02 + 0.3 * u(rng)) * std::max(wx, wy)};
    cam.target = {L.origin_x + u(rng) * wx, L.origin_y + u(rng) * wy, zlo + u(rng) * (zhi - zlo)};
    if (std::hypot(cam.target[0] - cam.eye[0], cam.target[1] - cam.eye[1]) < 1e-3 * std::max(wx, wy)) cam.target[0] += 0.1 * wx;
    cam.fovy_deg = 30 + 60 * u(rng);
    cam.width = 640, cam.height = 480;
    cam.near = 1e-3 * std::max(wx, wy);
    cam.tau_px = 0.25 * std::pow(256.0, u(rng));  // 0.25 .. 64 px: fine and coarse selections
    // Every triangle of the view, then split by the hole rule (docs/terrainlod.md §5): the
    // drawn ones must meet edge to edge, and an edge with nothing drawn across must have a
    // hole's triangle across.
    const Extraction x = extract_view(pyr, cam, 1, false);
    std::vector<terrainlod::DrawnTriangle> tris, holes;
    for (const auto& [id, tri] : x.parts)
      for (const auto& t : tri.triangles) {
        const terrainlod::DrawnTriangle d{{tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
                                           tri.vertices[static_cast<std::size_t>(t[2])]},
                                          id};
        const bool hole = nodata && terrainlod::covers_nodata(*nodata, {{{d.v[0].gx, d.v[0].gy}, {d.v[1].gx, d.v[1].gy}, {d.v[2].gx, d.v[2].gy}}});
        (hole ? holes : tris).push_back(d);
      }
    hole_triangles += holes.size();
    const terrainlod::HoleEdgeCount edges = terrainlod::count_open_edges(L, x.selection, tris, holes);
    open_total += edges.open;
    hole_edges += edges.hole_edges;
    // What extract draws is exactly the triangles kept here.
    const Extraction drawn = extract_view(pyr, cam);
    if (drawn.triangles != tris.size()) ++drawn_over_nodata;
    tiles_total += x.selection.tiles.size();
    for (const auto& s : x.selection.tiles) levels_seen.insert(s.id.level);
  }
  bar.finish();
  j["cameras"] = args.cameras;
  j["camera_tiles"] = tiles_total;
  j["camera_levels_seen"] = levels_seen.size();
  j["open_edges"] = open_total;
  ok = ok && open_total == 0;
  j["nodata"] = nodata ? "hole" : "fill";
  if (nodata) {
    j["nodata_samples"] = nodata->samples;
    j["hole_triangles"] = hole_triangles;
    j["hole_edges"] = hole_edges;
    j["views_drawing_other_triangles"] = drawn_over_nodata;
    ok = ok && drawn_over_nodata == 0;
  }
  j["ok"] = ok;
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return ok ? 0 : 1;
}

}  // namespace fest::terrainlod_tool

#include "terrainlod/pyramid_build.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "terrainlod/rtin_start.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/tin_reference.hpp"

namespace fest::terrainlod {
namespace {

int log2_int(int n) {
  int b = 0;
  while ((1 << b) < n) ++b;
  return b;
}

std::int64_t finest_code(double z, double delta_min) { return std::llround(z / delta_min); }

// The lattice mesh of a tile: (n+1)^2 DEM samples `step` cells apart, each lattice cell
// split by its shorter diagonal (docs/terrainlod.md §1, on the tile's lattice), border points locked.
// On the DEM's own grid (step 1) the cells take the reference surface's diagonals, whatever
// --diagonal chose: that mesh is the reference itself, exact at the leaves' limit 0.
struct StartMesh {
  Tin tin;
  std::vector<std::uint8_t> locked;
};

StartMesh lattice_mesh(const ReferenceSurface& ref, const HeightGrid& padded, int x0, int y0, int n, int step) {
  StartMesh s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int gx = x0 + i * step, gy = y0 + j * step;
      s.tin.vertices.push_back({double(gx), double(gy), padded.at(gx, gy)});
      s.locked.push_back(i == 0 || j == 0 || i == n || j == n ? 1 : 0);
    }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto& v = s.tin.vertices;
      const double d_ne = std::abs(v[id(i + 1, j + 1)].z - v[id(i, j)].z);
      const double d_nw = std::abs(v[id(i, j + 1)].z - v[id(i + 1, j)].z);
      if (step == 1 ? ref.ne_diagonal(x0 + i, y0 + j) : d_ne <= d_nw) {
        s.tin.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.tin.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.tin.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.tin.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return s;
}

TileFrame frame_of(const LevelInfo& lv, const std::vector<LevelInfo>& levels, int tx, int ty) {
  TileFrame f;
  f.x0 = tx * lv.cells;
  f.y0 = ty * lv.cells;
  f.x1 = f.x0 + lv.cells;
  f.y1 = f.y0 + lv.cells;
  if (lv.level + 1 < static_cast<int>(levels.size())) {
    const LevelInfo& fine = levels[static_cast<std::size_t>(lv.level) + 1];
    f.fine_step = fine.cells >> fine.lattice_bits;
    if (tx > 0) f.refinable |= 1u << kWest;
    if (ty > 0) f.refinable |= 1u << kSouth;
    if (tx + 1 < lv.tiles_x) f.refinable |= 1u << kEast;
    if (ty + 1 < lv.tiles_y) f.refinable |= 1u << kNorth;
  }
  return f;
}

// Whether the unsimplified lattice mesh of every tile of the level meets the engine's
// limit (the engine only removes vertices, so it cannot repair a start mesh that fails).
bool lattice_fits(const ReferenceSurface& ref, const HeightGrid& padded, const LevelInfo& lv,
                  const std::vector<LevelInfo>& levels, int threads) {
  const int n = 1 << lv.lattice_bits, step = lv.cells / n;
  const int tiles = lv.tiles_x * lv.tiles_y;
  // Tiles are checked in parallel; the answer (all fit?) does not depend on the order.
  std::atomic<bool> fits{true};
  parallel_for(static_cast<std::size_t>(tiles), threads, [&](std::size_t j) {
    if (!fits.load()) return;  // one misfit settles it: the rest is skipped
    const int k = static_cast<int>(j);
    const int tx = k % lv.tiles_x, ty = k / lv.tiles_x;
    const StartMesh s = lattice_mesh(ref, padded, tx * lv.cells, ty * lv.cells, n, step);
    const TileFrame f = frame_of(lv, levels, tx, ty);
    for (const auto& t : s.tin.triangles)
      if (transition_error(ref, f, s.tin.vertices[t[0]], s.tin.vertices[t[1]], s.tin.vertices[t[2]], lv.limit) > lv.limit) {
        fits.store(false);
        return;
      }
  });
  return fits.load();
}

// A coarse RTIN on the tile's lattice whose every triangle (with its transition variants)
// meets the engine's limit, all border points locked (rtin_start.hpp); nullopt where some
// lattice cell fits with neither diagonal (then the lattice mesh does not fit either).
std::optional<StartMesh> rtin_tile_start(const ReferenceSurface& ref, const TinReference* coarse, const TileFrame& frame,
                                         int n, int step, double limit) {
  std::vector<std::uint8_t> border(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) border[static_cast<std::size_t>(j) * (n + 1) + i] = 1;
  TriangleMeasure measure;
  if (coarse)
    measure = [&](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
      return transition_error(*coarse, ref, frame, a, b, c, s);
    };
  else
    measure = [&](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
      return transition_error(ref, frame, a, b, c, s);
    };
  PointHeight height;
  if (coarse)
    height = [coarse](double x, double y) { return coarse->height_at(x, y); };
  else
    height = [&ref](double x, double y) { return ref.height_at(x, y); };
  auto rtin = rtin_start_mesh(ref, SquareLattice{frame.x0, frame.y0, n, step}, border, limit, measure, height);
  if (!rtin) return std::nullopt;
  return StartMesh{std::move(rtin->tin), std::move(rtin->locked)};
}

Tile build_tile(const ReferenceSurface& ref, const TinReference* coarse, const HeightGrid& padded, const LevelInfo& lv,
                const std::vector<LevelInfo>& levels, int tx, int ty, double delta_min, double tolerance, StartRule rule) {
  const int n = 1 << lv.lattice_bits, step = lv.cells / n;
  const TileFrame frame = frame_of(lv, levels, tx, ty);
  const double limit = lv.limit + tolerance;
  std::optional<StartMesh> start;
  // With no tolerance (the leaves by default) the engine only removes vertices inside
  // planar regions: the result is nearly the start mesh, and the lattice's diagonals (the
  // DEM surface's own) are both exact and what the strip coder packs best.
  if (rule == StartRule::rtin && lv.limit > 0) start = rtin_tile_start(ref, coarse, frame, n, step, limit);
  if (!start) start = lattice_mesh(ref, padded, frame.x0, frame.y0, n, step);
  const SimplifyResult r = coarse ? simplify_tin(*coarse, ref, start->tin, start->locked, limit, &frame)
                                  : simplify_tin(ref, start->tin, start->locked, limit, &frame);

  Tile tile;
  tile.id = {lv.level, tx, ty};
  tile.lattice_bits = lv.lattice_bits;
  tile.k = lv.k;
  tile.refinable = frame.refinable;
  tile.eps = static_cast<float>(lv.eps);
  if (frame.fine_step > 0) tile.fine_bits = levels[static_cast<std::size_t>(lv.level) + 1].lattice_bits;
  for (const auto& p : r.mesh.vertices) {
    TileVertex v;
    v.X = (static_cast<int>(p.x) - frame.x0) / step;
    v.Y = (static_cast<int>(p.y) - frame.y0) / step;
    const std::int64_t g = finest_code(p.z, delta_min);
    v.code = tile.on_border(v) ? g : (g >> lv.k);  // arithmetic shift = floor division
    tile.vertices.push_back(v);
  }
  tile.triangles = r.mesh.triangles;
  for (int s = kWest; s <= kNorth; ++s) {
    if (!(frame.refinable & (1u << s))) continue;
    const bool vertical = s == kWest || s == kEast;
    const int fixed = s == kWest ? frame.x0 : s == kEast ? frame.x1 : s == kSouth ? frame.y0 : frame.y1;
    const int from = vertical ? frame.y0 : frame.x0;
    for (int a = from; a <= from + lv.cells; a += frame.fine_step) {
      if ((a - from) % step == 0) continue;  // on this tile's own lattice
      const int gx = vertical ? fixed : a, gy = vertical ? a : fixed;
      tile.fine_G[s].push_back(finest_code(padded.at(gx, gy), delta_min));
    }
  }
  return tile;
}

// The level a level-l tile is measured against, or -1 for the DEM's grid.
int reference_level(const BuildParams& params, int l, int L) {
  if (l == L || params.reference == Reference::original) return -1;
  const int r = params.reference == Reference::level_plus_1 ? l + 1 : std::min(l + 2, L);
  // Level L with no leaf tolerance is the DEM's surface: measure on the grid.
  return r == L && params.leaf_error == 0 ? -1 : r;
}

// The finished base triangulations of level r under the square of tile (l, tx, ty) as
// one reference mesh; nullopt where one of them does not exist (tiles beyond the DEM's
// extent, in the padding: those tiles are measured against the DEM instead).
std::optional<TinReference> coarse_reference(const std::vector<TileTriangulation>& base, const LevelInfo& lr,
                                             const LevelInfo& lv, int tx, int ty) {
  const int f = lv.cells / lr.cells;
  std::vector<GridPoint> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int iy = ty * f; iy < (ty + 1) * f; ++iy)
    for (int ix = tx * f; ix < (tx + 1) * f; ++ix) {
      if (ix >= lr.tiles_x || iy >= lr.tiles_y) return std::nullopt;
      const TileTriangulation& t = base[static_cast<std::size_t>(iy) * lr.tiles_x + ix];
      if (t.triangles.empty()) return std::nullopt;
      const int offset = static_cast<int>(vertices.size());
      for (const auto& v : t.vertices) vertices.push_back({double(v.gx), double(v.gy), v.z});
      for (const auto& tri : t.triangles) triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
    }
  const int x0 = tx * lv.cells, y0 = ty * lv.cells;
  return TinReference(std::move(vertices), std::move(triangles), x0, y0, x0 + lv.cells, y0 + lv.cells,
                      std::max(1, lv.cells / 32));
}

}  // namespace

HeightGrid pad_grid(const HeightGrid& grid, int padded) {
  HeightGrid p;
  p.width = p.height = padded;
  p.h.resize(static_cast<std::size_t>(padded) * padded);
  for (int j = 0; j < padded; ++j)
    for (int i = 0; i < padded; ++i)
      p.h[static_cast<std::size_t>(j) * padded + i] = grid.at(std::min(i, grid.width - 1), std::min(j, grid.height - 1));
  return p;
}

double triangulation_error(const ReferenceSurface& ref, const TileTriangulation& t) {
  double worst = 0;
  for (const auto& tri : t.triangles) {
    GridPoint p[3];
    for (int k = 0; k < 3; ++k) {
      const auto& v = t.vertices[static_cast<std::size_t>(tri[k])];
      p[k] = {double(v.gx), double(v.gy), v.z};
    }
    worst = std::max(worst, triangle_error(ref, p[0], p[1], p[2], std::numeric_limits<double>::infinity()));
  }
  return worst;
}

TileErrorRange tile_error(const ReferenceSurface& ref, const Tile& tile, const TileGeometry& geometry) {
  using V = TileTriangulation::Vertex;
  TileErrorRange r;
  // Every distinct triangle of all the masks once: gathered, sorted and deduplicated (one
  // allocation; a std::set allocated a node per triangle).
  std::vector<std::array<V, 3>> measured;
  bool first = true;
  for (unsigned m = 0; m < 16; ++m) {
    if ((m & tile.refinable) != m) continue;
    ++r.triangulations;
    const TileTriangulation tri = triangulate(tile, m, geometry);
    for (const auto& v : tri.vertices) {
      if (first || v.z < r.z_min) r.z_min = v.z;
      if (first || v.z > r.z_max) r.z_max = v.z;
      first = false;
    }
    for (const auto& t : tri.triangles) {
      std::array<V, 3> key{tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
                           tri.vertices[static_cast<std::size_t>(t[2])]};
      std::sort(key.begin(), key.end());
      measured.push_back(key);
    }
  }
  // One triangulation (the leaves, tiles without finer neighbours) has no duplicates.
  if (r.triangulations > 1) {
    std::sort(measured.begin(), measured.end());
    measured.erase(std::unique(measured.begin(), measured.end()), measured.end());
  }
  for (const auto& key : measured) {
    GridPoint p[3];
    for (int k = 0; k < 3; ++k) p[k] = {double(key[static_cast<std::size_t>(k)].gx), double(key[static_cast<std::size_t>(k)].gy), key[static_cast<std::size_t>(k)].z};
    // The error of a triangle does not depend on its orientation.
    if (twice_area(p[0], p[1], p[2]) < 0) std::swap(p[1], p[2]);
    r.err = std::max(r.err, triangle_error(ref, p[0], p[1], p[2], std::numeric_limits<double>::infinity()));
  }
  return r;
}

Pyramid build_pyramid_streaming(const HeightGrid& grid, double dx, double dy, const BuildParams& params,
                                const TileSink& sink, const std::function<void(std::size_t, std::size_t)>& progress) {
  const PyramidPlan plan = plan_pyramid(grid.width, grid.height, dx, dy, params.pyramid);
  if (!(params.z_quantum > 0) || !std::isfinite(params.z_quantum))
    throw usage_error("finest height quantum must be a positive number (got {})", params.z_quantum);
  if (!(params.height_quantum > 0) || !(params.height_quantum <= 1))
    throw usage_error("interior height quantum must be in (0, 1] of eps_l (got {})", params.height_quantum);
  if (!(params.leaf_error >= 0) || !std::isfinite(params.leaf_error))
    throw usage_error("leaf tolerance must be a finite number >= 0 (got {})", params.leaf_error);
  const int texels = params.pyramid.texels == 0 ? params.pyramid.tile : params.pyramid.texels;

  Pyramid pyr;
  pyr.levels = plan.levels;
  pyr.padded = plan.padded;
  pyr.width = grid.width;
  pyr.height = grid.height;
  pyr.delta_min = params.z_quantum;
  const HeightGrid padded = pad_grid(grid, plan.padded);
  const ReferenceSurface ref(padded, params.diagonal);
  double lo = padded.h[0], hi = lo;
  for (double z : padded.h) lo = std::min(lo, z), hi = std::max(hi, z);
  // Finest height codes must stay within the format's range (tile.hpp).
  if (std::max(std::fabs(lo), std::fabs(hi)) / params.z_quantum >= std::ldexp(1.0, kMaxHeightBits))
    throw usage_error("heights up to {} in steps of {} need codes beyond the tile format's 2^{}; a coarser finest height "
                      "quantum fits them",
                      std::max(std::fabs(lo), std::fabs(hi)), params.z_quantum, kMaxHeightBits);
  const double tolerance = 1e-9 * std::max(1.0, hi - lo);

  for (const auto& lp : plan.level) {
    LevelInfo lv;
    lv.level = lp.level;
    lv.tiles_x = lp.tiles_x;
    lv.tiles_y = lp.tiles_y;
    lv.cells = params.pyramid.tile << (plan.levels - lp.level);
    lv.lattice_bits = log2_int(std::min(texels, lv.cells));
    const bool leaf = lp.level == plan.levels;
    lv.eps = leaf ? params.leaf_error : lp.eps;
    // Clamped as a double: a huge eps / delta_min must not reach the int conversion.
    lv.k = leaf ? 0
                : static_cast<int>(std::clamp(std::floor(std::log2(params.height_quantum * lv.eps / pyr.delta_min)), 0.0,
                                              double{kMaxHeightBits}));
    // Quantization moves a height by at most half a bucket of 2^k finest steps.
    lv.limit = leaf ? lv.eps : std::max(0.0, lv.eps - std::ldexp(pyr.delta_min, lv.k) / 2);
    pyr.level.push_back(lv);
  }
  // Lattice refinement where a level's texel lattice cannot carry its budget (steep
  // sub-texel detail): one more bit per axis until the unsimplified lattice fits (the full
  // DEM always does), then the finer levels get at least half the coarser lattice, so
  // every coarse border point is also a fine one.
  for (int l = plan.levels - 1; l >= 0; --l) {
    LevelInfo& lv = pyr.level[static_cast<std::size_t>(l)];
    while ((1 << lv.lattice_bits) < lv.cells && !lattice_fits(ref, padded, lv, pyr.level, std::max(1, params.threads))) {
      if (lv.lattice_bits == kMaxLatticeBits)
        throw usage_error("level {} would need a tile lattice finer than 2^{} steps per side to keep its error budget; "
                          "smaller tiles or a larger tolerance fit",
                          l, kMaxLatticeBits);
      ++lv.lattice_bits;
    }
  }
  for (int l = 1; l <= plan.levels; ++l)
    pyr.level[static_cast<std::size_t>(l)].lattice_bits =
        std::max(pyr.level[static_cast<std::size_t>(l)].lattice_bits, pyr.level[static_cast<std::size_t>(l) - 1].lattice_bits - 1);

  // Level by level from the leaves up; within a level, chunks of whole rows are built in
  // parallel and handed to the sink in transmission order, so only one chunk of tiles is
  // held at a time and the order (hence the archive's bytes) does not depend on threads.
  std::size_t total = 0, done = 0;
  for (const auto& lv : pyr.level) total += static_cast<std::size_t>(lv.tiles_x) * lv.tiles_y;
  const int threads = std::max(1, params.threads);
  const int L = plan.levels;
  // Base triangulations of the levels that still serve as a reference, by tile.
  std::vector<std::vector<TileTriangulation>> base(static_cast<std::size_t>(L) + 1);
  std::vector<int> last_user(static_cast<std::size_t>(L) + 1, -1);  // lowest level measured against it
  for (int l = L; l >= 0; --l) {
    const int r = reference_level(params, l, L);
    if (r >= 0) last_user[static_cast<std::size_t>(r)] = l;
  }
  for (int l = L; l >= 0; --l) {
    const LevelInfo& lv = pyr.level[static_cast<std::size_t>(l)];
    const int r = reference_level(params, l, L);
    if (last_user[static_cast<std::size_t>(l)] >= 0)
      base[static_cast<std::size_t>(l)].resize(static_cast<std::size_t>(lv.tiles_x) * lv.tiles_y);
    const int rows_per_chunk = std::max(1, (4 * threads + lv.tiles_x - 1) / lv.tiles_x);
    for (int row0 = 0; row0 < lv.tiles_y; row0 += rows_per_chunk) {
      const int row1 = std::min(lv.tiles_y, row0 + rows_per_chunk);
      const std::size_t count = static_cast<std::size_t>(row1 - row0) * lv.tiles_x;
      std::vector<Tile> chunk(count);
      std::vector<std::string> bytes(count);
      parallel_for(count, threads, [&](std::size_t j) {
        const int tx = static_cast<int>(j % static_cast<std::size_t>(lv.tiles_x));
        const int ty = row0 + static_cast<int>(j / static_cast<std::size_t>(lv.tiles_x));
        std::optional<TinReference> coarse;
        if (r >= 0)
          coarse = coarse_reference(base[static_cast<std::size_t>(r)], pyr.level[static_cast<std::size_t>(r)], lv, tx, ty);
        Tile t = build_tile(ref, coarse ? &*coarse : nullptr, padded, lv, pyr.level, tx, ty, pyr.delta_min, tolerance,
                            params.start);
        if (!base[static_cast<std::size_t>(l)].empty())
          base[static_cast<std::size_t>(l)][static_cast<std::size_t>(ty) * lv.tiles_x + tx] = triangulate(t, 0, pyr.geometry(l));
        // The tile's own figures: the largest error over its triangulations (with
        // quantized heights) against the DEM, and its height range, for stats and culling.
        const TileErrorRange e = tile_error(ref, t, pyr.geometry(l));
        t.err = static_cast<float>(e.err);
        t.z_min = static_cast<float>(e.z_min);
        t.z_max = static_cast<float>(e.z_max);
        bytes[j] = encode_tile(t);  // here, in parallel: coding costs about a tenth of building
        chunk[j] = std::move(t);
      });
      for (std::size_t j = 0; j < count; ++j) sink(std::move(chunk[j]), std::move(bytes[j]));
      done += count;
      if (progress) progress(done, total);
    }
    // References no level below this one needs any more.
    for (int k = l; k <= L; ++k)
      if (last_user[static_cast<std::size_t>(k)] == l) std::vector<TileTriangulation>().swap(base[static_cast<std::size_t>(k)]);
  }
  return pyr;
}

Pyramid build_pyramid(const HeightGrid& grid, double dx, double dy, const BuildParams& params,
                      const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<Tile> tiles;
  Pyramid pyr = build_pyramid_streaming(grid, dx, dy, params, [&](Tile&& t, std::string&&) { tiles.push_back(std::move(t)); }, progress);
  // Leaves first from the builder; transmission order is the root first.
  std::stable_sort(tiles.begin(), tiles.end(), [](const Tile& a, const Tile& b) { return a.id.level < b.id.level; });
  pyr.tiles = std::move(tiles);
  return pyr;
}

}  // namespace fest::terrainlod

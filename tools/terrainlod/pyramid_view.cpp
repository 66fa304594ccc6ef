#include "pyramid_view.hpp"

#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/json_value.hpp"
#include "core/stopwatch.hpp"
#include "terrainlod/dem_clip.hpp"
#include "formats/image/image_io.hpp"

namespace fest::terrainlod_tool {
namespace {

struct VertexKeyHash {
  std::size_t operator()(const terrainlod::TileTriangulation::Vertex& v) const {
    std::uint64_t z;
    std::memcpy(&z, &v.z, sizeof z);
    std::uint64_t h = static_cast<std::uint64_t>(v.gx) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(v.gy) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h ^= z + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

}  // namespace

// Level colours for the meshes and renderings (coarse = blue ... fine = red).
OpenMesh::Vec3uc level_colour(int level, int levels) {
  static const unsigned char palette[8][3] = {{49, 54, 149},  {69, 117, 180}, {116, 173, 209}, {171, 217, 233},
                                              {254, 224, 144}, {253, 174, 97}, {244, 109, 67},  {215, 48, 39}};
  const int k = levels == 0 ? 7 : static_cast<int>(std::lround(7.0 * level / levels));
  return {palette[k][0], palette[k][1], palette[k][2]};
}

Extent extent_of(const PyramidFile& pyr, bool clip) {
  return {json_integer<std::int64_t>(pyr.manifest().at("width")) - 1, json_integer<std::int64_t>(pyr.manifest().at("height")) - 1, clip};
}

// Triangulations of several tiles -> one mesh in world coordinates; vertices shared by
// tiles (exactly equal grid position and height) become one vertex, so a crack-free
// selection gives a connected mesh. Faces coloured by level.
Mesh world_mesh(const PyramidFile& pyr, const Parts& parts, const Extent& extent) {
  const auto& L = pyr.layout();
  Mesh mesh;
  mesh.request_face_colors();
  std::size_t vertices = 0, triangles = 0;
  for (const auto& part : parts) vertices += part.second.vertices.size(), triangles += part.second.triangles.size();
  // Every triangle has three edges, each shared by two: about 1.5 edges per triangle.
  mesh.reserve(vertices, triangles + triangles / 2 + 1, triangles);
  // A hash map: a tree map's lookups were a quarter of a large view's extraction time.
  std::unordered_map<terrainlod::TileTriangulation::Vertex, Mesh::VertexHandle, VertexKeyHash> ids;
  std::vector<Mesh::VertexHandle> handles;
  std::map<std::array<double, 3>, Mesh::VertexHandle> cut_points;  // --clip: points on the DEM's edges
  for (const auto& part : parts) {
    // Named references, not a structured binding: C++17 lambdas cannot capture those (clang).
    const auto& id = part.first;
    const auto& tri = part.second;
    handles.assign(tri.vertices.size(), Mesh::VertexHandle());
    const std::int64_t cells = L.cells[static_cast<std::size_t>(id.level)];
    const std::int64_t x0 = id.x * cells, y0 = id.y * cells;
    auto handle = [&](int k) {
      Mesh::VertexHandle& h = handles[static_cast<std::size_t>(k)];
      if (h.is_valid()) return h;
      const auto& v = tri.vertices[static_cast<std::size_t>(k)];
      auto add = [&] {
        return mesh.add_vertex(Mesh::Point(L.origin_x + static_cast<double>(v.gx) * L.dx,
                                           L.origin_y + static_cast<double>(v.gy) * L.dy, v.z));
      };
      // Only points on the tile's border can be shared with another tile.
      if (v.gx != x0 && v.gy != y0 && v.gx != x0 + cells && v.gy != y0 + cells) return h = add();
      auto [it, added] = ids.try_emplace(v);
      if (added) it->second = add();
      return h = it->second;
    };
    // Without --clip every vertex is used: keep them in tile order.
    if (!extent.clip)
      for (std::size_t k = 0; k < tri.vertices.size(); ++k) handle(static_cast<int>(k));
    const auto colour = level_colour(id.level, L.levels);
    for (const auto& t : tri.triangles) {
      const std::array<terrainlod::TileTriangulation::Vertex, 3> v{
          tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
          tri.vertices[static_cast<std::size_t>(t[2])]};
      if (!extent.crosses(v)) {
        const auto f = mesh.add_face(handle(t[0]), handle(t[1]), handle(t[2]));
        if (f.is_valid()) mesh.set_color(f, colour);
        continue;
      }
      // Cut at the DEM's edges: corners that stay are the tile's own vertices; cut points
      // are shared by exact position (the same edge gives the same point in every tile).
      for (const auto& piece : terrainlod::clip_to_dem(v, extent.last_x, extent.last_y)) {
        Mesh::VertexHandle h[3];
        for (int c = 0; c < 3; ++c) {
          const auto& p = piece[static_cast<std::size_t>(c)];
          for (int k = 0; k < 3 && !h[c].is_valid(); ++k)
            if (p.x == static_cast<double>(v[static_cast<std::size_t>(k)].gx) && p.y == static_cast<double>(v[static_cast<std::size_t>(k)].gy))
              h[c] = handle(t[k]);
          if (h[c].is_valid()) continue;
          auto [it, added] = cut_points.try_emplace(std::array<double, 3>{p.x, p.y, p.z});
          if (added) it->second = mesh.add_vertex(Mesh::Point(L.origin_x + p.x * L.dx, L.origin_y + p.y * L.dy, p.z));
          h[c] = it->second;
        }
        const auto f = mesh.add_face(h[0], h[1], h[2]);
        if (f.is_valid()) mesh.set_color(f, colour);
      }
    }
  }
  return mesh;
}

cv::Mat decode_texture(PyramidFile& pyr, const terrainlod::TileId& id) {
  const std::string_view bytes = pyr.texture_bytes(id);
  Image img;
  try {
    img = formats::read_image(bytes, pyr.texture_extension() == "png" ? formats::Format::png : formats::Format::jpeg);
  } catch (const Error& e) {
    throw bad_input("texture of tile {}/{}/{}: {} ({})", id.level, id.x, id.y, e.what(), pyr.name());
  }
  const int T = pyr.layout().texels;
  if (img.pixels.cols != T || img.pixels.rows != T || img.pixels.depth() != CV_8U ||
      (img.pixels.channels() != 1 && img.pixels.channels() != 3))
    throw bad_input("texture of tile {}/{}/{} is {} x {} pixels with {} channels; the pyramid has {} x {} 8-bit grey or RGB ({})",
                    id.level, id.x, id.y, img.pixels.cols, img.pixels.rows, img.pixels.channels(), T, T, pyr.name());
  return img.pixels;
}

terrainlod::Camera parse_camera(const nlohmann::json& j, const std::string& where) {
  terrainlod::Camera c;
  try {
    auto vec3 = [&](const char* key, std::array<double, 3>& v) {
      if (!j.contains(key)) return false;
      const auto& a = j.at(key);
      if (!a.is_array() || a.size() != 3) throw bad_input("camera '{}' must be [x, y, z] ({})", key, where);
      for (int k = 0; k < 3; ++k) v[static_cast<std::size_t>(k)] = a.at(static_cast<std::size_t>(k)).get<double>();
      return true;
    };
    if (!vec3("eye", c.eye) || !vec3("target", c.target)) throw bad_input("camera needs 'eye' and 'target' ({})", where);
    vec3("up", c.up);
    c.fovy_deg = j.value("fovy_deg", 60.0);
    c.width = json_integer_or<int>(j, "width", 1920);
    c.height = json_integer_or<int>(j, "height", 1080);
    c.near = j.value("near", 1.0);
    c.far = j.value("far", 1e9);
    c.tau_px = j.value("tau_px", 1.0);
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("camera is malformed: {} ({})", e.what(), where);
  }
  try {
    terrainlod::check_camera(c);
  } catch (const Error& e) {
    throw Error(e.status(), fmt::format("{} ({})", e.what(), where));
  }
  return c;
}

Extraction extract_view(PyramidFile& pyr, const terrainlod::Camera& cam, double z_scale, bool cut_holes,
                        const ProgressFn& progress) {
  Extraction x;
  const auto t0 = SteadyClock::now();
  x.selection = terrainlod::select_tiles(pyr.layout(), cam, [&](const terrainlod::TileId& id) {
    x.examined.insert(id);
    const auto [z_min, z_max] = pyr.z_range(id);
    // Widen the float range by a relative hair so the box holds the double heights.
    const double pad = 1e-6 * (std::abs(z_min) + std::abs(z_max) + 1);
    return std::array<double, 2>{(z_min - pad) * z_scale, (z_max + pad) * z_scale};
  });
  x.select_ms = ms_since(t0);
  const auto t1 = SteadyClock::now();
  for (const auto& s : x.selection.tiles) {
    x.parts.emplace_back(s.id, terrainlod::triangulate(pyr.tile(s.id), s.mask, pyr.geometry(s.id.level)));
    if (cut_holes && pyr.nodata()) x.hole_triangles += terrainlod::cut_holes(*pyr.nodata(), x.parts.back().second);
    x.triangles += x.parts.back().second.triangles.size();
    if (progress) progress(x.parts.size(), x.selection.tiles.size());
  }
  x.decode_ms = ms_since(t1);
  return x;
}

void scale_heights(Mesh& mesh, double k) {
  if (k == 1) return;
  for (auto vh : mesh.vertices()) {
    auto p = mesh.point(vh);
    p[2] *= k;
    mesh.set_point(vh, p);
  }
}

terrainlod::WorldBox drawn_box(PyramidFile& pyr, bool clip, double z_scale) {
  const auto& L = pyr.layout();
  const double cx = clip ? pyr.manifest().at("width").get<double>() - 1 : static_cast<double>(L.tiles_x[0]) * L.cells[0];
  const double cy = clip ? pyr.manifest().at("height").get<double>() - 1 : static_cast<double>(L.tiles_y[0]) * L.cells[0];
  // Every drawn height is a tile vertex's, a finer neighbour's border point (a vertex of
  // that tile) or, with --clip, interpolated between them: the union of all tiles' height
  // ranges (their headers) holds them all.
  double z0 = 0, z1 = 0;
  bool first = true;
  for (const auto& f : pyr.index()) {
    const auto z = pyr.z_range(f.id);
    if (first || z[0] < z0) z0 = z[0];
    if (first || z[1] > z1) z1 = z[1];
    first = false;
  }
  // The headers hold floats: widen by a relative hair, as extract_view does.
  const double pad = 1e-6 * (std::abs(z0) + std::abs(z1) + 1);
  z0 -= pad, z1 += pad;
  // With holes only the valid samples' box can be drawn (every drawn vertex is a valid
  // sample, or beyond the DEM the padding of a valid edge sample).
  double x0 = 0, y0 = 0, x1 = cx, y1 = cy;
  std::array<int, 4> valid{};
  if (pyr.nodata() && terrainlod::valid_bounds(*pyr.nodata(), valid)) {
    x0 = valid[0], y0 = valid[1];
    x1 = valid[2] == pyr.nodata()->width - 1 ? cx : valid[2];
    y1 = valid[3] == pyr.nodata()->height - 1 ? cy : valid[3];
  }
  return {L.origin_x + x0 * L.dx, L.origin_y + y0 * L.dy, std::min(z0, z1) * z_scale, L.origin_x + x1 * L.dx,
          L.origin_y + y1 * L.dy, std::max(z0, z1) * z_scale};
}

nlohmann::json tiles_per_level(const PyramidFile& pyr, const terrainlod::Selection& sel) {
  std::vector<int> n(static_cast<std::size_t>(pyr.layout().levels) + 1, 0);
  for (const auto& s : sel.tiles) ++n[static_cast<std::size_t>(s.id.level)];
  return n;
}

// Walking a pyramid root first (transmission order), once level l starts the tiles above
// it are needed only as parents of progressive tiles: drop every decoded tile but level
// l - 1's (keep_only keeps their ancestors), so memory holds about one level of tiles.
void keep_parents_only(PyramidFile& pyr, int level) {
  std::set<terrainlod::TileId> keep;
  for (const auto& f : pyr.index())
    if (f.id.level == level - 1) keep.insert(f.id);
  pyr.keep_only(keep);
}

}  // namespace fest::terrainlod_tool

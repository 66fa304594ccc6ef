// build, decode, extract, verify and stats of a pyramid: formats/dem -> lib/terrainlod ->
// the .tlp archive (pyramid_file) -> formats/mesh, JSON.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <cstring>
#include <map>
#include <unordered_map>
#include <atomic>
#include <optional>
#include <thread>
#include <mutex>
#include <random>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/file_io.hpp"
#include "core/mesh.hpp"
#include "core/progress.hpp"
#include "core/resources.hpp"
#include "core/threads.hpp"
#include "dem_input.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "pyramid_file.hpp"
#include "pyramid_options.hpp"
#include "render.hpp"
#include "terrainlod/extract.hpp"
#include "terrainlod/progressive_recode.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/quantized_mesh.hpp"
#include "terrainlod/texture_pyramid.hpp"
#include "terrainlod/tile_codec.hpp"
#include "formats/image/image_io.hpp"

namespace fest::terrainlod_tool {
namespace {

formats::OutputFormat mesh_output(const std::string& path, const std::string& to) {
  formats::OutputFormat out = !to.empty() ? formats::output_format_from_name(to)
                              : is_stdio(path) ? formats::OutputFormat{formats::Format::ply, false}
                                               : formats::output_format_from_path(path);
  if (formats::kind_of(out.format) != formats::Kind::mesh)
    throw usage_error("output must be a mesh format (ply, obj, off, stl, drc), not {}", formats::format_name(out.format));
  return out;
}

PyramidFile open_pyramid(const std::string& path) { return PyramidFile::open(path); }

// Level colours for the meshes and renderings (coarse = blue ... fine = red).
OpenMesh::Vec3uc level_colour(int level, int levels) {
  static const unsigned char palette[8][3] = {{49, 54, 149},  {69, 117, 180}, {116, 173, 209}, {171, 217, 233},
                                              {254, 224, 144}, {253, 174, 97}, {244, 109, 67},  {215, 48, 39}};
  const int k = levels == 0 ? 7 : static_cast<int>(std::lround(7.0 * level / levels));
  return {palette[k][0], palette[k][1], palette[k][2]};
}

// --clip: a triangle entirely in the padding east or north of the DEM (every vertex on or
// beyond the last sample column, or row) covers nothing of the DEM.
struct Extent {
  std::int64_t last_x = 0, last_y = 0;  // grid index of the last sample column and row
  bool clip = false;
  bool outside(const std::array<terrainlod::TileTriangulation::Vertex, 3>& v) const {
    return clip && ((v[0].gx >= last_x && v[1].gx >= last_x && v[2].gx >= last_x) ||
                    (v[0].gy >= last_y && v[1].gy >= last_y && v[2].gy >= last_y));
  }
};

Extent extent_of(const PyramidFile& pyr, bool clip) {
  return {pyr.manifest().at("width").get<std::int64_t>() - 1, pyr.manifest().at("height").get<std::int64_t>() - 1, clip};
}

using Parts = std::vector<std::pair<terrainlod::TileId, terrainlod::TileTriangulation>>;

// Triangulations of several tiles -> one mesh in world coordinates; vertices shared by
// tiles (exactly equal grid position and height) become one vertex, so a crack-free
// selection gives a connected mesh. Faces coloured by level.
// Welding key of a decoded vertex: exact grid position and height (the bits of z, so
// that equal doubles meet; heights are never -0 or NaN here).
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

Mesh world_mesh(const PyramidFile& pyr, const Parts& parts, const Extent& extent = {}) {
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
  for (const auto& [id, tri] : parts) {
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
      if (extent.outside({tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
                          tri.vertices[static_cast<std::size_t>(t[2])]}))
        continue;
      const auto f = mesh.add_face(handle(t[0]), handle(t[1]), handle(t[2]));
      if (f.is_valid()) mesh.set_color(f, colour);
    }
  }
  return mesh;
}

// A textured view: every tile keeps its own vertices (a vertex on a tile border has a
// different texture coordinate in each tile), with (u, v) in the texture of the tile it
// is drawn with -- its own, or for a closing-only tile the chosen ancestor's, mapped to
// the sub-square (seed footnote 3). Faces in tile order, coloured by level.
struct TexturedMesh {
  Mesh mesh;
  std::vector<terrainlod::TileId> sources;  // texture tiles used, sorted
  std::vector<int> face_source;              // per face: index into sources
  std::vector<std::string> face_material;    // OBJ output: per face
  std::string mtllib;
};

TexturedMesh textured_mesh(const PyramidFile& pyr, const terrainlod::Selection& sel, const Parts& parts, const Extent& extent) {
  const auto& L = pyr.layout();
  TexturedMesh out;
  out.mesh.request_face_colors();
  out.mesh.request_vertex_texcoords2D();
  std::map<terrainlod::TileId, terrainlod::TileId> source_of;
  for (const auto& s : sel.tiles) source_of[s.id] = s.texture;
  for (const auto& [id, src] : source_of) out.sources.push_back(src);
  std::sort(out.sources.begin(), out.sources.end());
  out.sources.erase(std::unique(out.sources.begin(), out.sources.end()), out.sources.end());
  for (const auto& [id, tri] : parts) {
    const terrainlod::TileId src = source_of.at(id);  // parts are the selection's tiles
    const int k = static_cast<int>(std::lower_bound(out.sources.begin(), out.sources.end(), src) - out.sources.begin());
    // Texture coordinates in the source tile: the tile's own square is the sub-square
    // (ox, oy) of 2^d x 2^d in its ancestor d levels up.
    const int d = id.level - src.level;
    const double cells = L.cells[static_cast<std::size_t>(id.level)], parts_per_side = std::ldexp(1.0, d);
    const double ox = id.x - static_cast<double>(src.x) * parts_per_side, oy = id.y - static_cast<double>(src.y) * parts_per_side;
    std::vector<Mesh::VertexHandle> handles(tri.vertices.size());
    for (const auto& t : tri.triangles) {
      if (extent.outside({tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
                          tri.vertices[static_cast<std::size_t>(t[2])]}))
        continue;
      for (int c = 0; c < 3; ++c) {
        auto& h = handles[static_cast<std::size_t>(t[c])];
        if (h.is_valid()) continue;
        const auto& v = tri.vertices[static_cast<std::size_t>(t[c])];
        h = out.mesh.add_vertex(Mesh::Point(L.origin_x + static_cast<double>(v.gx) * L.dx, L.origin_y + static_cast<double>(v.gy) * L.dy, v.z));
        const double u = (ox + (static_cast<double>(v.gx) - id.x * cells) / cells) / parts_per_side;
        const double w = (oy + (static_cast<double>(v.gy) - id.y * cells) / cells) / parts_per_side;
        out.mesh.set_texcoord2D(h, Mesh::TexCoord2D(static_cast<float>(u), static_cast<float>(w)));
      }
      const auto f = out.mesh.add_face(handles[static_cast<std::size_t>(t[0])], handles[static_cast<std::size_t>(t[1])],
                                       handles[static_cast<std::size_t>(t[2])]);
      if (!f.is_valid()) continue;
      out.mesh.set_color(f, level_colour(id.level, L.levels));
      out.face_source.push_back(k);
    }
  }
  return out;
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

// One atlas for the textures of a view: a grid of (T + 2)-texel cells, each texture with a
// one-texel border of its own edge texels, so bilinear filtering at a tile's edge does not
// bleed in the neighbouring cell. Returns the atlas; `cells` receives each texture's
// (x0, y0) texel offset (top-left of the T x T square, rows from the top).
cv::Mat make_atlas(const std::vector<cv::Mat>& images, int T, std::vector<std::array<int, 2>>& cells) {
  const int n = static_cast<int>(images.size());
  const int cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
  const int rows = std::max(1, (n + cols - 1) / cols);
  const int type = images.empty() ? CV_8UC3 : images[0].type();
  cv::Mat atlas(rows * (T + 2), cols * (T + 2), type, cv::Scalar::all(0));
  cells.clear();
  for (int k = 0; k < n; ++k) {
    const int x0 = (k % cols) * (T + 2), y0 = (k / cols) * (T + 2);
    cv::Mat bordered;
    cv::copyMakeBorder(images[static_cast<std::size_t>(k)], bordered, 1, 1, 1, 1, cv::BORDER_REPLICATE);
    bordered.copyTo(atlas(cv::Rect(x0, y0, T + 2, T + 2)));
    cells.push_back({x0 + 1, y0 + 1});
  }
  return atlas;
}

// Texture coordinates of every vertex moved from its tile texture into the atlas.
void map_to_atlas(TexturedMesh& tm, cv::Size atlas, const std::vector<std::array<int, 2>>& cells, int T) {
  std::vector<char> done(tm.mesh.n_vertices(), 0);
  for (auto fh : tm.mesh.faces()) {
    const auto& cell = cells[static_cast<std::size_t>(tm.face_source[static_cast<std::size_t>(fh.idx())])];
    for (auto vh : tm.mesh.fv_range(fh)) {
      if (done[static_cast<std::size_t>(vh.idx())]) continue;
      done[static_cast<std::size_t>(vh.idx())] = 1;
      const auto t = tm.mesh.texcoord2D(vh);
      const double u = (cell[0] + t[0] * T) / atlas.width;
      const double v = 1 - (cell[1] + (1 - t[1]) * T) / atlas.height;
      tm.mesh.set_texcoord2D(vh, Mesh::TexCoord2D(static_cast<float>(u), static_cast<float>(v)));
    }
  }
}

// OBJ text with a material library: "mtllib" first, then "usemtl" before every run of
// faces with the same material (the writer emits faces in mesh order).
std::string obj_with_materials(const std::string& obj, const std::string& mtllib, const std::vector<std::string>& face_material) {
  std::string out = "mtllib " + mtllib + "\n";
  std::size_t face = 0, at = 0;
  std::string current;
  while (at < obj.size()) {
    std::size_t end = obj.find('\n', at);
    end = end == std::string::npos ? obj.size() : end + 1;
    if (obj.compare(at, 2, "f ") == 0 && face < face_material.size()) {
      if (face_material[face] != current) out += "usemtl " + (current = face_material[face]) + "\n";
      ++face;
    }
    out.append(obj, at, end - at);
    at = end;
  }
  return out;
}

std::string material_block(const std::string& name, const std::string& map) {
  return "newmtl " + name + "\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " + map + "\n";
}

std::string tile_name(const terrainlod::TileId& id) {
  return std::to_string(id.level) + "-" + std::to_string(id.x) + "-" + std::to_string(id.y);
}

}  // namespace

terrainlod::TileId parse_tile(const std::string& s) {
  terrainlod::TileId id;
  char a = 0, b = 0;
  std::istringstream in(s);
  if (!(in >> id.level >> a >> id.x >> b >> id.y) || a != '/' || b != '/' || !in.eof() || id.level < 0 || id.x < 0 || id.y < 0)
    throw usage_error("--tile expects L/X/Y (got '{}')", s);
  return id;
}

namespace {

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
    c.width = j.value("width", 1920);
    c.height = j.value("height", 1080);
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

struct Extraction {
  terrainlod::Selection selection;
  std::set<terrainlod::TileId> examined;  // tiles whose box the selection looked at
  std::vector<std::pair<terrainlod::TileId, terrainlod::TileTriangulation>> parts;
  std::size_t triangles = 0;
  double select_ms = 0, decode_ms = 0;
};

Extraction extract_view(PyramidFile& pyr, const terrainlod::Camera& cam) {
  Extraction x;
  const auto t0 = SteadyClock::now();
  x.selection = terrainlod::select_tiles(pyr.layout(), cam, [&](const terrainlod::TileId& id) {
    x.examined.insert(id);
    const auto [z_min, z_max] = pyr.z_range(id);
    // Widen the float range by a relative hair so the box holds the double heights.
    const double pad = 1e-6 * (std::abs(z_min) + std::abs(z_max) + 1);
    return std::array<double, 2>{z_min - pad, z_max + pad};
  });
  x.select_ms = ms_since(t0);
  const auto t1 = SteadyClock::now();
  for (const auto& s : x.selection.tiles) {
    x.parts.emplace_back(s.id, terrainlod::triangulate(pyr.tile(s.id), s.mask, pyr.geometry(s.id.level)));
    x.triangles += x.parts.back().second.triangles.size();
  }
  x.decode_ms = ms_since(t1);
  return x;
}

nlohmann::json tiles_per_level(const PyramidFile& pyr, const terrainlod::Selection& sel) {
  std::vector<int> n(static_cast<std::size_t>(pyr.layout().levels) + 1, 0);
  for (const auto& s : sel.tiles) ++n[static_cast<std::size_t>(s.id.level)];
  return n;
}

Image read_texture(const std::string& path) {
  const std::string bytes = read_input(path);
  const std::string where = is_stdio(path) ? "-" : path;
  try {
    const formats::Format f = formats::detect_format(bytes, where);
    if (formats::kind_of(f) != formats::Kind::image) throw bad_input("texture is not an image but {}", formats::format_name(f));
    Image img = formats::read_image(bytes, f);
    img.pixels = terrainlod::texture_pixels(img.pixels);
    return img;
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    const std::string what = e.what();
    throw bad_input("{}", what.find(where) == std::string::npos ? fmt::format("{} ({})", what, where) : what);
  }
}

// A prefiltered texture pyramid PREFIX_<k>.png (k = 0 full size, each level about half the
// previous), as `resample mip build` writes it. Level files are read while they exist.
std::vector<Image> read_texture_mip(const std::string& prefix) {
  std::vector<Image> mips;
  std::error_code ec;
  for (int k = 0;; ++k) {
    const std::string png = prefix + "_" + std::to_string(k) + ".png", exr = prefix + "_" + std::to_string(k) + ".exr";
    if (std::filesystem::exists(png, ec)) {
      mips.push_back(read_texture(png));
    } else if (std::filesystem::exists(exr, ec)) {
      throw bad_input("texture pyramid level {} is floating point; texture tiles are 8-bit: build it from an 8 or 16-bit image ({})", k, exr);
    } else {
      break;
    }
  }
  if (mips.empty()) throw io_error("no texture pyramid level {}_0.png", prefix);
  for (std::size_t k = 1; k < mips.size(); ++k) {
    const cv::Mat& a = mips[k - 1].pixels;
    const cv::Mat& b = mips[k].pixels;
    if (std::abs(b.cols - a.cols / 2) > 1 || std::abs(b.rows - a.rows / 2) > 1 || b.channels() != a.channels())
      throw bad_input("texture pyramid level {} is {} x {} with {} channels after {} x {} with {}; each level must halve the previous ({}_{}.png)",
                      k, b.cols, b.rows, b.channels(), a.cols, a.rows, a.channels(), prefix, k);
  }
  return mips;
}

// The canvas of one level from a prefiltered pyramid: its coarsest image that still has a
// pixel per texel there (the finest, where none has), resampled like a single image with
// the level's tiles as leaves.
cv::Mat mip_canvas(const std::vector<Image>& mips, int level, const terrainlod::Pyramid& pyr, int tile, int texels, const LoadedDem& dem) {
  const int cells = tile << (pyr.levels - level);
  std::size_t k = 0;
  while (k + 1 < mips.size() &&
         static_cast<double>(mips[k + 1].pixels.cols) / (dem.grid.width - 1) * cells / texels >= 1.0 &&
         static_cast<double>(mips[k + 1].pixels.rows) / (dem.grid.height - 1) * cells / texels >= 1.0)
    ++k;
  const cv::Mat& img = mips[k].pixels;
  terrainlod::TextureLayout lay{level, cells, texels, dem.grid.width, dem.grid.height};
  return terrainlod::leaf_canvas(img, terrainlod::place_image(img.cols, img.rows, dem.grid.width, dem.grid.height), lay);
}

// Every tile's texture, encoded, in the order of `tiles`. The canvases come from one
// image (the leaf canvas, box-filtered per level) or from a prefiltered pyramid (`mips`).
std::vector<std::string> texture_tiles(const terrainlod::Pyramid& pyr, const std::vector<TileEntry>& tiles, const cv::Mat& pixels, terrainlod::ImagePlacement placement,
                                       const std::optional<terrainlod::ImageFrame>& georeferenced, const BuildArgs& args,
                                       int texels, const LoadedDem& dem, const std::vector<Image>& mips) {
  terrainlod::TextureLayout lay;
  lay.levels = pyr.levels;
  lay.tile = args.tile;
  lay.texels = texels;
  lay.width = dem.grid.width;
  lay.height = dem.grid.height;
  formats::ImageWriteOptions opt;
  const formats::Format format = args.texture_format == TextureFormat::jpeg ? formats::Format::jpeg : formats::Format::png;
  if (format == formats::Format::jpeg) opt.jpeg_quality = args.texture_quality;
  std::map<terrainlod::TileId, std::size_t> at;
  for (std::size_t i = 0; i < tiles.size(); ++i) at[tiles[i].id] = i;
  std::vector<std::string> out(tiles.size());
  cv::Mat canvas = !mips.empty()     ? cv::Mat()
                   : georeferenced ? terrainlod::leaf_canvas(pixels, *georeferenced, lay)
                                   : terrainlod::leaf_canvas(pixels, placement, lay);
  for (int l = pyr.levels; l >= 0; --l) {
    if (!mips.empty()) canvas = mip_canvas(mips, l, pyr, args.tile, texels, dem);
    else if (l < pyr.levels) canvas = terrainlod::halve_canvas(canvas);
    const auto& lv = pyr.level[static_cast<std::size_t>(l)];
    std::vector<std::pair<terrainlod::TileId, std::size_t>> jobs;
    for (int y = 0; y < lv.tiles_y; ++y)
      for (int x = 0; x < lv.tiles_x; ++x) {
        const auto it = at.find({l, x, y});
        if (it != at.end()) jobs.push_back({it->first, it->second});
      }
    // Encoding is independent per tile: spread it over the build's threads.
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto work = [&] {
      try {
        for (std::size_t j; (j = next.fetch_add(1)) < jobs.size();) {
          Image tile;
          tile.pixels = terrainlod::tile_texture(canvas, l, jobs[j].first.x, jobs[j].first.y, texels);
          out[jobs[j].second] = formats::write_image(tile, format, opt);
        }
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = jobs.size();
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < resolve_threads(args.threads); ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
  }
  return out;
}

}  // namespace

int run_build(const BuildArgs& args) {
  if (args.output.empty() || is_stdio(args.output)) throw usage_error("build needs -o PYRAMID.tlp or -o DIRECTORY/");
  const bool archive = args.output.size() >= 4 && args.output.substr(args.output.size() - 4) == ".tlp";
  terrainlod::BuildParams params;
  params.pyramid.tile = args.tile;
  params.pyramid.texels = args.texels;
  params.pyramid.error_fraction = args.error_fraction;
  check_tile_options(args.tile, args.texels, args.error_fraction);  // usage errors before reading
  params.height_quantum = args.height_quantum;
  params.leaf_error = args.leaf_error;
  params.reference = args.reference;
  params.diagonal = args.dem.diagonal;
  params.start = args.start;
  params.threads = resolve_threads(args.threads);
  if (args.z_quantum < 0 || !std::isfinite(args.z_quantum)) throw usage_error("--z-quantum must be positive (got {})", args.z_quantum);

  const auto t0 = SteadyClock::now();
  // The texture is read before the DEM's work starts, so a bad image costs nothing.
  std::optional<Image> texture_image;
  std::vector<Image> mips;
  if (!args.texture.empty() && args.texture != "hillshade") texture_image = read_texture(args.texture);
  if (!args.texture_mip.empty()) {
    mips = read_texture_mip(args.texture_mip);
    texture_image = mips[0];
  }
  const LoadedDem dem = load_dem(args.dem);
  std::optional<terrainlod::ImagePlacement> placement;
  std::optional<terrainlod::ImageFrame> georeferenced;
  const std::string texture_name = args.texture_mip.empty() ? args.texture : args.texture_mip + "_0.png";
  // A georeferenced image (GeoTIFF, or any image with a world file) on a georeferenced DEM
  // lies where its georeference says, whatever its size.
  if (texture_image && mips.empty() && !is_stdio(args.texture) && (dem.raster.georeferenced || !args.dem.origin.empty())) {
    formats::RasterGeoreference g;
    try {
      g = formats::read_georeference(args.texture);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;  // GDAL cannot read it: OpenCV did, unplaced
    }
    if (g.georeferenced) {
      const terrainlod::ImageFrame f = terrainlod::georeferenced_frame(
          {dem.origin_x, dem.origin_y, dem.dx, dem.dy, dem.grid.height}, {g.origin_x, g.origin_y, g.dx, g.dy, g.height});
      const int iw = texture_image->pixels.cols, ih = texture_image->pixels.rows;
      const double px0 = f.ox, px1 = (dem.grid.width - 1) * f.sx + f.ox, py0 = f.oy, py1 = (dem.grid.height - 1) * f.sy + f.oy;
      if (px1 < -0.5 || px0 > iw - 0.5 || py1 < -0.5 || py0 > ih - 0.5)
        throw bad_input("texture's georeference does not overlap the DEM ({})", args.texture);
      georeferenced = f;
    }
  }
  if (texture_image && !georeferenced) {
    try {
      placement = terrainlod::place_image(texture_image->pixels.cols, texture_image->pixels.rows, dem.grid.width, dem.grid.height);
    } catch (const Error& e) {
      throw Error(e.status(), fmt::format("{} ({})", e.what(), texture_name));
    }
  }
  const double read_ms = ms_since(t0);
  const bool integer = dem.raster.integer && args.dem.z_scale == 1 && std::floor(args.dem.z_offset) == args.dem.z_offset;
  params.z_quantum = args.z_quantum > 0 ? args.z_quantum : integer ? 1.0 : 0.01;
  check_quantum_options(args.height_quantum, args.leaf_error);

  const auto t1 = SteadyClock::now();
  Progress bar("build", 0, progress_wanted(args.progress));
  // Finished tiles go to one temporary spill file per level as they come (leaves first);
  // the archive is then the head and the levels' blobs in transmission order (root first),
  // so memory holds one chunk of tiles, never the pyramid.
  struct Spill {
    std::FILE* file = nullptr;
    std::vector<TileEntry> entries;
  };
  std::vector<Spill> spill;
  auto close_spills = [&] {
    for (auto& s : spill)
      if (s.file) std::fclose(s.file);
  };
  std::size_t tile_count = 0;
  terrainlod::Pyramid pyr;
  try {
    pyr = terrainlod::build_pyramid_streaming(
        dem.grid, dem.dx, dem.dy, params,
        [&](terrainlod::Tile&& t, std::string&& blob) {
          const auto l = static_cast<std::size_t>(t.id.level);
          if (spill.size() <= l) spill.resize(l + 1);
          if (!spill[l].file && !(spill[l].file = std::tmpfile())) throw io_error("cannot create a temporary spill file");
          if (std::fwrite(blob.data(), 1, blob.size(), spill[l].file) != blob.size())
            throw io_error("cannot write the temporary spill file");
          spill[l].entries.push_back({t.id, 0, static_cast<std::uint32_t>(blob.size())});
          ++tile_count;
        },
        [&](std::size_t done, std::size_t) { bar.set(done); });
  } catch (...) {
    close_spills();
    throw;
  }
  bar.finish();
  const double build_ms = ms_since(t1);
  std::vector<TileEntry> entries;  // index order: the levels root first, as spilled
  for (const auto& sp : spill) entries.insert(entries.end(), sp.entries.begin(), sp.entries.end());

  nlohmann::json levels = nlohmann::json::array();
  for (const auto& lv : pyr.level)
    levels.push_back({{"level", lv.level}, {"tiles_x", lv.tiles_x}, {"tiles_y", lv.tiles_y}, {"cells", lv.cells},
                      {"lattice_bits", lv.lattice_bits}, {"k", lv.k}, {"eps", lv.eps}, {"limit", lv.limit}});
  const int texels = args.texels == 0 ? args.tile : args.texels;
  nlohmann::json manifest = {{"format", "terrainlod-pyramid"},
                             {"version", 1},
                             {"width", dem.grid.width},
                             {"height", dem.grid.height},
                             {"origin", {dem.origin_x, dem.origin_y}},
                             {"cell_size", {dem.dx, dem.dy}},
                             {"crs", dem.raster.crs},
                             {"tile", args.tile},
                             {"texels", texels},
                             {"error_fraction", args.error_fraction},
                             {"height_quantum", args.height_quantum},
                             {"z_quantum", params.z_quantum},
                             {"leaf_error", args.leaf_error},
                             {"diagonal", diagonal_name(args.dem.diagonal)},
                             {"levels", pyr.levels},
                             {"padded", pyr.padded},
                             {"coding", coding_name(args.coding)},
                             {"connectivity", "strips"},
                             {"reference", reference_name(args.reference)},
                             {"level", levels},
                             {"texture", nullptr},
                             {"tool", "terrainlod 1"}};
  // Texture tiles (spec 2.1, 2.9): the image (or a hillshade of the DEM) resampled to the
  // leaf canvas, box-filtered level by level, cut into T x T tiles.
  const auto t3 = SteadyClock::now();
  std::vector<std::string> textures;
  std::size_t texture_bytes = 0;
  if (!args.texture.empty() || !mips.empty()) {
    const bool hillshade = args.texture == "hillshade";
    const cv::Mat pixels = hillshade ? terrainlod::hillshade_image(dem.grid, dem.dx, dem.dy) : texture_image->pixels;
    textures = texture_tiles(pyr, entries, pixels, hillshade || !placement ? terrainlod::ImagePlacement::samples : *placement, georeferenced,
                             args, texels, dem, mips);
    for (const auto& t : textures) texture_bytes += t.size();
    manifest["texture"] = {{"format", args.texture_format == TextureFormat::jpeg ? "jpeg" : "png"},
                           {"texels", texels},
                           {"channels", pixels.channels()},
                           {"source", hillshade ? "hillshade" : std::filesystem::path(texture_name).filename().string()},
                           {"placement", georeferenced ? "georeferenced"
                                         : hillshade || *placement == terrainlod::ImagePlacement::samples ? "samples" : "extent"},
                           {"filter", mips.empty() ? "2x2 box mean per level" : "prefiltered pyramid (--texture-mip), one level per tile level"}};
    if (args.texture_format == TextureFormat::jpeg) manifest["texture"]["quality"] = args.texture_quality;
  }
  const double texture_ms = ms_since(t3);
  for (std::size_t i = 0; i < textures.size(); ++i) entries[i].texture_length = static_cast<std::uint32_t>(textures[i].size());
  const auto t2 = SteadyClock::now();
  std::uint64_t file_bytes = 0;
  try {
    // The spilled blobs in index order (the levels' files one after the other), each
    // handed to `emit` with its tile's texture and its index entry (the length is the
    // final one). Progressive coding recodes each level against the level before it
    // (spec 2.8): that level's standalone blobs are kept (coded, small) and only the
    // parents of the chunk of rows at hand are decoded.
    const bool progressive = args.coding == Coding::progressive;
    auto for_each_tile = [&](auto&& emit) {
      std::string parent_store, level_store;            // standalone blobs of the previous / this level
      std::vector<std::size_t> parent_at, level_at;     // their offsets (one more at the end)
      std::size_t i = 0;
      for (std::size_t l = 0; l < spill.size(); ++l) {
        auto& sp = spill[l];
        if (!sp.file) continue;  // a level without tiles
        std::rewind(sp.file);
        const int tiles_x = pyr.level[l].tiles_x;
        // Chunks of whole even rows: a parent row serves two child rows.
        const std::size_t rows = static_cast<std::size_t>(std::max(2, 2 * ((8 * params.threads + 2 * tiles_x - 1) / (2 * tiles_x))));
        level_store.clear();
        level_at.assign(1, 0);
        for (std::size_t first = 0; first < sp.entries.size(); first += rows * static_cast<std::size_t>(tiles_x)) {
          const std::size_t last = std::min(sp.entries.size(), first + rows * static_cast<std::size_t>(tiles_x));
          for (std::size_t k = first; k < last; ++k) {
            const std::size_t at = level_store.size();
            level_store.resize(at + sp.entries[k].length);
            if (std::fread(level_store.data() + at, 1, sp.entries[k].length, sp.file) != sp.entries[k].length)
              throw io_error("cannot read back the temporary spill file");
            level_at.push_back(level_store.size());
          }
          std::vector<std::string> recoded;
          if (progressive && l > 0) {
            std::vector<terrainlod::CodedTile> children, parents;
            for (std::size_t k = first; k < last; ++k)
              children.push_back({sp.entries[k].id, std::string_view(level_store).substr(level_at[k], level_at[k + 1] - level_at[k])});
            const std::size_t ptx = static_cast<std::size_t>(pyr.level[l - 1].tiles_x);
            const std::size_t p0 = static_cast<std::size_t>(sp.entries[first].id.y / 2) * ptx;
            const std::size_t p1 = std::min(parent_at.size() - 1, static_cast<std::size_t>(sp.entries[last - 1].id.y / 2 + 1) * ptx);
            for (std::size_t k = p0; k < p1; ++k)
              parents.push_back({spill[l - 1].entries[k].id, std::string_view(parent_store).substr(parent_at[k], parent_at[k + 1] - parent_at[k])});
            recoded = terrainlod::recode_progressive(children, parents, params.threads);
          }
          for (std::size_t k = first; k < last; ++k, ++i) {
            const std::string_view blob = recoded.empty() ? std::string_view(level_store).substr(level_at[k], level_at[k + 1] - level_at[k])
                                                          : std::string_view(recoded[k - first]);
            entries[i].length = static_cast<std::uint32_t>(blob.size());
            emit(entries[i], blob, textures.empty() ? std::string_view() : std::string_view(textures[i]));
          }
        }
        parent_store.swap(level_store);
        parent_at.swap(level_at);
      }
    };
    if (archive) {
      // The index holds each tile's final length, known only once it is recoded: the head
      // is written as a placeholder of its (fixed) size and filled in at the end.
      std::string head = terrainlod::encode_tlp_head(manifest.dump(), entries);
      AtomicFile out(args.output);
      std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
      if (!f) throw io_error("cannot write {}", args.output);
      bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
      file_bytes = head.size();
      try {
        for_each_tile([&](const TileEntry&, std::string_view blob, std::string_view texture) {
          ok = ok && std::fwrite(blob.data(), 1, blob.size(), f) == blob.size();
          // An empty view may hold a null pointer, which fwrite must not get.
          if (!texture.empty()) ok = ok && std::fwrite(texture.data(), 1, texture.size(), f) == texture.size();
          file_bytes += blob.size() + texture.size();
        });
        const std::string final_head = terrainlod::encode_tlp_head(manifest.dump(), entries);
        if (final_head.size() != head.size()) throw runtime_failure("archive head changed size");
        ok = ok && std::fseek(f, 0, SEEK_SET) == 0 && std::fwrite(final_head.data(), 1, final_head.size(), f) == final_head.size();
      } catch (...) {
        std::fclose(f);
        throw;
      }
      ok = (std::fclose(f) == 0) && ok;
      if (!ok) throw io_error("cannot write {}", args.output);
      out.commit();
    } else {
      DirectoryPyramidWriter out(args.output, manifest, args.texture_format == TextureFormat::jpeg ? "jpg" : "png");
      for_each_tile([&](const TileEntry& e, std::string_view blob, std::string_view texture) {
        out.add(e.id, blob, texture);
        file_bytes += blob.size() + texture.size();
      });
      out.commit();
    }
  } catch (...) {
    close_spills();
    throw;
  }
  close_spills();
  const double write_ms = ms_since(t2);
  if (!args.report.empty()) {
    nlohmann::json r = {{"tiles", tile_count},
                        {"bytes", file_bytes},
                        {"texture_bytes", texture_bytes},
                        {"container", archive ? "archive" : "directory"},
                        {"time_ms", {{"read", read_ms}, {"build", build_ms}, {"texture", texture_ms}, {"write", write_ms}}},
                        {"threads", params.threads},
                        {"peak_rss_kb", peak_rss_kb()}};
    write_output(args.report, r.dump(2) + "\n");
  }
  return 0;
}

namespace {

// Walking a pyramid root first (transmission order), once level l starts the tiles above
// it are needed only as parents of progressive tiles: drop every decoded tile but level
// l - 1's (keep_only keeps their ancestors), so memory holds about one level of tiles.
void keep_parents_only(PyramidFile& pyr, int level) {
  std::set<terrainlod::TileId> keep;
  for (const auto& f : pyr.index())
    if (f.id.level == level - 1) keep.insert(f.id);
  pyr.keep_only(keep);
}

}  // namespace

int run_pyramid_stats(const std::string& path) {
  PyramidFile pyr = open_pyramid(path);
  const int L = pyr.layout().levels;
  struct Acc {
    std::size_t tiles = 0, vertices = 0, border = 0, triangles = 0, header = 0, vert = 0, conn = 0, refine = 0, texture = 0;
    std::size_t standalone = 0, progressive = 0, progressive_tiles = 0, inherited_present = 0;
    double worst = 0;
  };
  std::vector<Acc> acc(static_cast<std::size_t>(L) + 1);
  int level_at = -1;
  for (const auto& e : pyr.index()) {
    if (e.id.level != level_at) keep_parents_only(pyr, level_at = e.id.level);
    const auto& t = pyr.tile(e.id);
    auto& a = acc[static_cast<std::size_t>(e.id.level)];
    ++a.tiles;
    a.vertices += t.vertices.size();
    a.border += 4 * static_cast<std::size_t>(t.n());
    a.triangles += t.triangles.size();
    // Both codings of the tile with its stream's strip order (spec 2.8: "stats give both
    // sizes"): the stored one is one of them, byte for byte (verify checks that).
    const std::string_view bytes = pyr.tile_bytes(e.id);
    const terrainlod::Tile* parent =
        e.id.level > 0 && pyr.has(terrainlod::parent_id(e.id)) ? &pyr.tile(terrainlod::parent_id(e.id)) : nullptr;
    terrainlod::TileSizes alone, prog;
    terrainlod::recode_tile(bytes, terrainlod::TileCoding::standalone, parent, &alone);
    terrainlod::recode_tile(bytes, terrainlod::TileCoding::progressive, parent, &prog);
    const terrainlod::TileSizes& s = terrainlod::tile_coding(bytes) == terrainlod::TileCoding::progressive ? prog : alone;
    a.header += s.header, a.vert += s.vertices, a.conn += s.connectivity, a.refine += s.refinement;
    a.standalone += alone.total(), a.progressive += prog.total();
    if (prog.coding == terrainlod::TileCoding::progressive) ++a.progressive_tiles, a.inherited_present += prog.inherited_present;
    a.texture += e.texture_length;
    if (t.eps > 0) a.worst = std::max(a.worst, static_cast<double>(t.err) / t.eps);
  }
  nlohmann::json levels = nlohmann::json::array();
  std::size_t total_v = 0, total_bytes = 0, total_t = 0, total_texture = 0, total_alone = 0, total_prog = 0;
  auto per_vertex = [](std::size_t bytes, std::size_t vertices) { return vertices ? static_cast<double>(bytes) / vertices : 0.0; };
  for (int l = 0; l <= L; ++l) {
    const auto& a = acc[static_cast<std::size_t>(l)];
    const auto& m = pyr.manifest().at("level").at(static_cast<std::size_t>(l));
    const std::size_t bytes_l = a.header + a.vert + a.conn + a.refine;
    total_v += a.vertices, total_bytes += bytes_l, total_t += a.triangles, total_texture += a.texture;
    total_alone += a.standalone, total_prog += a.progressive;
    levels.push_back({{"level", l},
                      {"tiles", a.tiles},
                      {"vertices", a.vertices},
                      {"border_vertices", a.border},
                      {"triangles", a.triangles},
                      {"eps", m.at("eps")},
                      {"lattice_bits", m.at("lattice_bits")},
                      {"bytes", {{"total", bytes_l}, {"header", a.header}, {"vertices", a.vert}, {"connectivity", a.conn},
                                 {"refinement", a.refine}, {"texture", a.texture}}},
                      {"bytes_per_vertex", per_vertex(bytes_l, a.vertices)},
                      {"standalone_bytes", a.standalone},
                      {"progressive_bytes", a.progressive},
                      {"progressive_tiles", a.progressive_tiles},
                      {"inherited_vertices_kept", a.inherited_present},
                      {"max_err_over_eps", l == L ? nlohmann::json(nullptr) : nlohmann::json(a.worst)}});
  }
  const double samples = pyr.manifest().at("width").get<double>() * pyr.manifest().at("height").get<double>();
  nlohmann::json j = {{"manifest", pyr.manifest()},
                      {"level", levels},
                      {"totals",
                       {{"tiles", pyr.index().size()},
                        {"vertices", total_v},
                        {"triangles", total_t},
                        {"coding", pyr.manifest().value("coding", std::string("standalone"))},
                        {"tile_bytes", total_bytes},
                        {"standalone_tile_bytes", total_alone},
                        {"progressive_tile_bytes", total_prog},
                        {"texture_bytes", total_texture},
                        {"file_bytes", pyr.size()},
                        {"bytes_per_vertex", per_vertex(total_bytes, total_v)},
                        {"standalone_bytes_per_vertex", per_vertex(total_alone, total_v)},
                        {"progressive_bytes_per_vertex", per_vertex(total_prog, total_v)},
                        {"bytes_per_sample", static_cast<double>(total_bytes) / samples},
                        {"ratio_to_raw_int16", static_cast<double>(total_bytes) / (2 * samples)}}}};
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

int run_decode(const DecodeArgs& args) {
  const terrainlod::TileId id = args.tile;
  if (args.mask < 0 || args.mask > 15) throw usage_error("--mask must be 0..15 (got {})", args.mask);
  const auto out = mesh_output(args.output, args.to);
  PyramidFile pyr = open_pyramid(args.pyramid);
  if (!pyr.has(id)) throw bad_input("pyramid has no tile {}/{}/{} ({})", id.level, id.x, id.y, pyr.name());
  const auto& t = pyr.tile(id);
  if ((static_cast<unsigned>(args.mask) & ~t.refinable) != 0)
    throw bad_input("tile {}/{}/{} has no finer neighbour on the sides of mask {} (refinable sides: {})", id.level, id.x, id.y,
                    args.mask, t.refinable);
  const std::string bytes = formats::write_mesh(
      world_mesh(pyr, {{id, terrainlod::triangulate(t, static_cast<unsigned>(args.mask), pyr.geometry(id.level))}}), out.format);
  std::string texture;
  if (!args.texture.empty()) texture = std::string(pyr.texture_bytes(id));
  formats::store_output(args.output, bytes, out.gzip);
  if (!texture.empty()) write_output(args.texture, texture);
  return 0;
}

// A frame's file name from a pattern with one %d or %0Nd.
std::string frame_name(const std::string& pattern, std::size_t frame, const char* flag) {
  const auto p = pattern.find('%');
  std::size_t q = p == std::string::npos ? p : p + 1;
  bool zero = false;
  if (q != std::string::npos && q < pattern.size() && pattern[q] == '0') zero = true, ++q;
  std::size_t width = 0;
  while (q != std::string::npos && q < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[q])))
    width = width * 10 + static_cast<std::size_t>(pattern[q++] - '0');
  if (p == std::string::npos || q >= pattern.size() || pattern[q] != 'd' || pattern.find('%', q) != std::string::npos || width > 12)
    throw usage_error("{} for --path needs one %d or %0Nd for the frame number (got '{}')", flag, pattern);
  std::string num = std::to_string(frame);
  if (num.size() < width) num.insert(0, width - num.size(), zero ? '0' : ' ');
  return pattern.substr(0, p) + num + pattern.substr(q + 1);
}

// extract --path: one mesh per camera; the decoded tiles persist between frames, with a
// one-tile ring of inactive tiles around the drawn ones of every level (seed 7.3.3), so
// small camera moves load nothing new.
int run_extract_path(const ExtractArgs& args, const formats::OutputFormat& out) {
  if (is_stdio(args.output)) throw usage_error("--path writes one file per frame: give -o with a %d pattern");
  frame_name(args.output, 0, "-o");
  if (!args.png.empty()) frame_name(args.png, 0, "--png");
  const std::string where = is_stdio(args.path) ? "-" : args.path;
  std::vector<terrainlod::Camera> cams;
  {
    std::istringstream lines(read_input(args.path));
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string at = fmt::format("{}:{}", where, n);
      nlohmann::json j;
      try {
        j = nlohmann::json::parse(line);
      } catch (const nlohmann::json::exception& e) {
        throw bad_input("camera is not JSON: {} ({})", e.what(), at);
      }
      cams.push_back(parse_camera(j, at));
      if (args.tau > 0) cams.back().tau_px = args.tau;
    }
  }
  if (cams.empty()) throw bad_input("camera path has no cameras ({})", where);
  if (!args.atlas.empty()) throw usage_error("--atlas is for one view (--camera), not a camera path");
  PyramidFile pyr = open_pyramid(args.pyramid);
  const auto& L = pyr.layout();
  std::map<terrainlod::TileId, cv::Mat> texture_cache;
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < cams.size(); ++k) {
    const std::size_t decoded0 = pyr.tiles_decoded(), bytes0 = pyr.bytes_touched();
    const Extraction x = extract_view(pyr, cams[k]);
    std::set<terrainlod::TileId> keep = x.examined;
    for (const auto& s : x.selection.tiles) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const terrainlod::TileId r{s.id.level, s.id.x + dx, s.id.y + dy};
          if (L.exists(r) && pyr.has(r)) keep.insert(r);
        }
    }
    for (const auto& id : keep) pyr.tile(id);  // prefetch the ring
    const std::size_t evicted = pyr.keep_only(keep);
    const Extent extent = extent_of(pyr, args.clip);
    std::optional<TexturedMesh> tm;
    RenderTextures textures;
    if (pyr.textured()) {
      tm = textured_mesh(pyr, x.selection, x.parts, extent);
      for (const auto& id : tm->sources) {
        // A texture is loaded once, with its tile, and kept while the tile is cached.
        if (!texture_cache.count(id)) texture_cache[id] = decode_texture(pyr, id);
        textures.images.push_back(texture_cache[id]);
      }
      textures.face_image = tm->face_source;
    }
    const Mesh mesh = tm ? tm->mesh : world_mesh(pyr, x.parts, extent);
    formats::store_output(frame_name(args.output, k, "-o"), formats::write_mesh(mesh, out.format), out.gzip);
    if (!args.png.empty()) write_output(frame_name(args.png, k, "--png"), render_png(mesh, cams[k], tm ? &textures : nullptr));
    for (auto it = texture_cache.begin(); it != texture_cache.end();) it = keep.count(it->first) ? std::next(it) : texture_cache.erase(it);
    frames.push_back({{"frame", k},
                      {"tiles", x.selection.tiles.size()},
                      {"tiles_per_level", tiles_per_level(pyr, x.selection)},
                      {"triangles", x.triangles},
                      {"tiles_loaded", pyr.tiles_decoded() - decoded0},
                      {"bytes_loaded", pyr.bytes_touched() - bytes0},
                      {"tiles_evicted", evicted},
                      {"tiles_cached", pyr.tiles_cached()},
                      {"time_ms", {{"select_close", x.select_ms}, {"decode", x.decode_ms}}}});
  }
  if (!args.report.empty()) write_output(args.report, nlohmann::json({{"frames", frames}}).dump(2) + "\n");
  return 0;
}

int run_extract(const ExtractArgs& args) {
  const auto out = mesh_output(args.output, args.to);
  if (args.tau < 0 || !std::isfinite(args.tau)) throw usage_error("--tau must be positive (got {})", args.tau);
  if (!args.path.empty()) return run_extract_path(args, out);
  if (args.camera.empty()) throw usage_error("extract needs --camera CAM.json or --path CAMS.jsonl");
  if (args.tau < 0 || !std::isfinite(args.tau)) throw usage_error("--tau must be positive (got {})", args.tau);
  const std::string cam_name = is_stdio(args.camera) ? "-" : args.camera;
  nlohmann::json cj;
  try {
    cj = nlohmann::json::parse(read_input(args.camera));
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("camera is not JSON: {} ({})", e.what(), cam_name);
  }
  terrainlod::Camera cam = parse_camera(cj, cam_name);
  if (args.tau > 0) cam.tau_px = args.tau;
  PyramidFile pyr = open_pyramid(args.pyramid);
  if (!args.atlas.empty() && !pyr.textured()) throw usage_error("--atlas needs a pyramid with textures (build --texture)");
  const Extraction x = extract_view(pyr, cam);
  const auto t2 = SteadyClock::now();
  const Extent extent = extent_of(pyr, args.clip);
  const bool obj_file = out.format == formats::Format::obj && !is_stdio(args.output);
  std::optional<TexturedMesh> tm;
  RenderTextures textures;
  std::vector<std::pair<std::string, std::string>> beside;  // files written next to the mesh
  std::size_t texture_count = 0;
  std::vector<std::array<int, 2>> atlas_cells;
  cv::Size atlas_size;
  if (pyr.textured()) {
    tm = textured_mesh(pyr, x.selection, x.parts, extent);
    texture_count = tm->sources.size();
    const bool need_pixels = !args.png.empty() || !args.atlas.empty();
    std::vector<std::string> face_material(tm->face_source.size());
    for (const auto& id : tm->sources) {
      if (need_pixels) textures.images.push_back(decode_texture(pyr, id));
      else pyr.texture_bytes(id);  // the bytes a viewer would load
    }
    textures.face_image = tm->face_source;
    namespace fs = std::filesystem;
    const fs::path obj_path(args.output);
    const std::string stem = obj_path.stem().string();
    std::string mtl;
    if (!args.atlas.empty()) {
      // The renderer keeps sampling the tile textures; the written mesh's coordinates
      // point into the atlas.
      Image atlas;
      atlas.pixels = make_atlas(textures.images, pyr.layout().texels, atlas_cells);
      atlas_size = atlas.pixels.size();
      beside.push_back({args.atlas, formats::write_image(atlas, formats::Format::png)});
      if (obj_file) {
        const fs::path rel = fs::absolute(args.atlas).lexically_relative(fs::absolute(obj_path).parent_path());
        mtl = material_block("atlas", rel.string());
        std::fill(face_material.begin(), face_material.end(), "atlas");
      }
    } else if (obj_file) {
      // One texture file per drawn tile texture beside the OBJ, one material each.
      for (std::size_t k = 0; k < tm->sources.size(); ++k) {
        const std::string name = "tile-" + tile_name(tm->sources[k]);
        const std::string file = stem + "-" + tile_name(tm->sources[k]) + "." + pyr.texture_extension();
        beside.push_back({(obj_path.parent_path() / file).string(), std::string(pyr.texture_bytes(tm->sources[k]))});
        mtl += material_block(name, file);
      }
      for (std::size_t f = 0; f < face_material.size(); ++f)
        face_material[f] = "tile-" + tile_name(tm->sources[static_cast<std::size_t>(tm->face_source[f])]);
    }
    if (obj_file) {
      beside.push_back({(obj_path.parent_path() / (stem + ".mtl")).string(), mtl});
      tm->face_material = std::move(face_material);
      tm->mtllib = stem + ".mtl";
    }
  }
  const Mesh mesh = tm ? tm->mesh : world_mesh(pyr, x.parts, extent);
  std::string png;
  if (!args.png.empty()) png = render_png(mesh, cam, tm ? &textures : nullptr);
  Mesh written = mesh;
  if (tm && !args.atlas.empty()) {
    TexturedMesh atlas_mesh{written, tm->sources, tm->face_source, {}, {}};
    map_to_atlas(atlas_mesh, atlas_size, atlas_cells, pyr.layout().texels);
    written = std::move(atlas_mesh.mesh);
  }
  std::string bytes = formats::write_mesh(written, out.format);
  if (tm && obj_file) bytes = obj_with_materials(bytes, tm->mtllib, tm->face_material);
  for (const auto& [file, content] : beside) write_output(file, content);
  formats::store_output(args.output, bytes, out.gzip);
  if (!png.empty()) write_output(args.png, png);
  if (!args.report.empty()) {
    std::size_t closing = 0;
    for (const auto& s : x.selection.tiles) closing += s.closing_only;
    nlohmann::json r = {{"tiles", x.selection.tiles.size()},
                        {"tiles_per_level", tiles_per_level(pyr, x.selection)},
                        {"closing_only", closing},
                        {"visited", x.selection.visited},
                        {"triangles", mesh.n_faces()},
                        {"vertices", mesh.n_vertices()},
                        {"textures", texture_count},
                        {"bytes_touched", pyr.bytes_touched()},
                        {"max_screen_error_px", pyr.manifest().at("error_fraction").get<double>() * cam.tau_px},
                        {"time_ms", {{"select_close", x.select_ms}, {"decode", x.decode_ms}, {"write", ms_since(t2)}}}};
    write_output(args.report, r.dump(2) + "\n");
  }
  return 0;
}

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
    if (dem->grid.width != pyr.manifest().at("width").get<int>() || dem->grid.height != pyr.manifest().at("height").get<int>())
      throw bad_input("DEM is {} x {} samples but the pyramid was built from {} x {} ({})", dem->grid.width, dem->grid.height,
                      pyr.manifest().at("width").get<int>(), pyr.manifest().at("height").get<int>(), dem->name);
    padded = terrainlod::pad_grid(dem->grid, pyr.manifest().at("padded").get<int>());
    ref.emplace(*padded, diagonal_rule(pyr.manifest().value("diagonal", std::string("short"))));
  }
  // The guarantee against the DEM for the reference the pyramid was built with (spec 2.2):
  // eps (1 + 1/4 + ...) = 4/3 eps for level l+2, eps (1 + 1/2 + ...) = 2 eps for l+1.
  const std::string reference = pyr.manifest().value("reference", std::string("l+2"));
  const double factor = reference == "original" ? 1.0 : reference == "l+1" ? 2.0 : 4.0 / 3.0;
  std::size_t triangulations = 0, reencode_mismatch = 0, over = 0;
  double worst_ratio = 0;
  int level_at = -1;
  for (const auto& e : pyr.index()) {
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
    for (const auto& e : pyr.index()) {
      try {
        decode_texture(pyr, e.id);
      } catch (const Error&) {
        ++bad_textures;
      }
    }
    j["bad_textures"] = bad_textures;
    ok = ok && bad_textures == 0;
  } else {
    j["bad_textures"] = nullptr;
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
  std::size_t open_total = 0, tiles_total = 0;
  std::set<int> levels_seen;
  for (int c = 0; c < args.cameras; ++c) {
    terrainlod::Camera cam;
    cam.eye = {L.origin_x + u(rng) * wx, L.origin_y + u(rng) * wy, zhi + (0.02 + 0.3 * u(rng)) * std::max(wx, wy)};
    cam.target = {L.origin_x + u(rng) * wx, L.origin_y + u(rng) * wy, zlo + u(rng) * (zhi - zlo)};
    if (std::hypot(cam.target[0] - cam.eye[0], cam.target[1] - cam.eye[1]) < 1e-3 * std::max(wx, wy)) cam.target[0] += 0.1 * wx;
    cam.fovy_deg = 30 + 60 * u(rng);
    cam.width = 640, cam.height = 480;
    cam.near = 1e-3 * std::max(wx, wy);
    cam.tau_px = 0.25 * std::pow(256.0, u(rng));  // 0.25 .. 64 px: fine and coarse selections
    const Extraction x = extract_view(pyr, cam);
    std::vector<terrainlod::DrawnTriangle> tris;
    for (const auto& [id, tri] : x.parts)
      for (const auto& t : tri.triangles)
        tris.push_back({{tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
                         tri.vertices[static_cast<std::size_t>(t[2])]},
                        id});
    open_total += terrainlod::count_open_edges(L, x.selection, tris);
    tiles_total += x.selection.tiles.size();
    for (const auto& s : x.selection.tiles) levels_seen.insert(s.id.level);
  }
  j["cameras"] = args.cameras;
  j["camera_tiles"] = tiles_total;
  j["camera_levels_seen"] = levels_seen.size();
  j["open_edges"] = open_total;
  ok = ok && open_total == 0;
  j["ok"] = ok;
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return ok ? 0 : 1;
}

}  // namespace fest::terrainlod_tool

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
    std::size_t bytes = 0;
    for (const auto& e : pyr.index()) {
      const auto g = pyr.geometry(e.id.level);
      terrainlod::QmFrame f;
      f.gx0 = static_cast<std::int64_t>(e.id.x) * g.cells;
      f.gy0 = static_cast<std::int64_t>(e.id.y) * g.cells;
      f.cells = g.cells;
      f.origin_x = L.origin_x, f.origin_y = L.origin_y, f.dx = L.dx, f.dy = L.dy;
      const std::string qm = terrainlod::encode_quantized_mesh(terrainlod::triangulate(pyr.tile(e.id), 0, g), f);
      const fs::path file = tmp / std::to_string(e.id.level) / std::to_string(e.id.x) / (std::to_string(e.id.y) + ".terrain");
      fs::create_directories(file.parent_path());
      std::ofstream out(file, std::ios::binary);
      out.write(qm.data(), static_cast<std::streamsize>(qm.size()));
      if (!out) throw io_error("cannot write {}", file.string());
      bytes += qm.size();
    }
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

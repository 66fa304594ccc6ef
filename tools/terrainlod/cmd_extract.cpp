// terrainlod extract: the crack-free mesh a camera needs (one view, or a camera path with the
// decoded tiles kept between frames), textured or coloured by level, and its rendering.

#include "commands.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/quote.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "pyramid_view.hpp"
#include "render.hpp"
#include "terrainlod/dem_clip.hpp"

namespace fest::terrainlod_tool {
namespace {

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
  for (const auto& part : parts) {
    // Named references, not a structured binding: the lambda below uses them, and clang
    // before 16 cannot capture a structured binding (the fuzz build uses clang 14).
    const auto& id = part.first;
    const auto& tri = part.second;
    const terrainlod::TileId src = source_of.at(id);  // parts are the selection's tiles
    const int k = static_cast<int>(std::lower_bound(out.sources.begin(), out.sources.end(), src) - out.sources.begin());
    // Texture coordinates in the source tile: the tile's own square is the sub-square
    // (ox, oy) of 2^d x 2^d in its ancestor d levels up.
    const int d = id.level - src.level;
    const double cells = L.cells[static_cast<std::size_t>(id.level)], parts_per_side = std::ldexp(1.0, d);
    const double ox = id.x - static_cast<double>(src.x) * parts_per_side, oy = id.y - static_cast<double>(src.y) * parts_per_side;
    std::vector<Mesh::VertexHandle> handles(tri.vertices.size());
    std::map<std::array<double, 3>, Mesh::VertexHandle> cut_points;  // --clip: points on the DEM's edges
    // A vertex at grid point (gx, gy), texture coordinates from its place in the tile.
    auto add = [&](double gx, double gy, double z) {
      const auto h = out.mesh.add_vertex(Mesh::Point(L.origin_x + gx * L.dx, L.origin_y + gy * L.dy, z));
      const double u = (ox + (gx - id.x * cells) / cells) / parts_per_side;
      const double w = (oy + (gy - id.y * cells) / cells) / parts_per_side;
      out.mesh.set_texcoord2D(h, Mesh::TexCoord2D(static_cast<float>(u), static_cast<float>(w)));
      return h;
    };
    auto corner = [&](int i) {
      auto& h = handles[static_cast<std::size_t>(i)];
      if (!h.is_valid()) {
        const auto& v = tri.vertices[static_cast<std::size_t>(i)];
        h = add(static_cast<double>(v.gx), static_cast<double>(v.gy), v.z);
      }
      return h;
    };
    auto face = [&](Mesh::VertexHandle a, Mesh::VertexHandle b, Mesh::VertexHandle c) {
      const auto f = out.mesh.add_face(a, b, c);
      if (!f.is_valid()) return;
      out.mesh.set_color(f, level_colour(id.level, L.levels));
      out.face_source.push_back(k);
    };
    for (const auto& t : tri.triangles) {
      const std::array<terrainlod::TileTriangulation::Vertex, 3> v{
          tri.vertices[static_cast<std::size_t>(t[0])], tri.vertices[static_cast<std::size_t>(t[1])],
          tri.vertices[static_cast<std::size_t>(t[2])]};
      if (!extent.crosses(v)) {
        face(corner(t[0]), corner(t[1]), corner(t[2]));
        continue;
      }
      for (const auto& piece : terrainlod::clip_to_dem(v, extent.last_x, extent.last_y)) {
        Mesh::VertexHandle h[3];
        for (int c = 0; c < 3; ++c) {
          const auto& p = piece[static_cast<std::size_t>(c)];
          for (int q = 0; q < 3 && !h[c].is_valid(); ++q)
            if (p.x == static_cast<double>(v[static_cast<std::size_t>(q)].gx) && p.y == static_cast<double>(v[static_cast<std::size_t>(q)].gy))
              h[c] = corner(t[q]);
          if (h[c].is_valid()) continue;
          auto [it, added] = cut_points.try_emplace(std::array<double, 3>{p.x, p.y, p.z});
          if (added) it->second = add(p.x, p.y, p.z);
          h[c] = it->second;
        }
        face(h[0], h[1], h[2]);
      }
    }
  }
  return out;
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
      } catch (const nlohmann::json::parse_error& e) {
        throw bad_input("camera is not JSON: {} ({})", json_failure_words(e.what(), e.byte, line), at);
      } catch (const nlohmann::json::exception& e) {
        throw bad_input("camera is not JSON: {} ({})", json_failure_words(e.what(), 0, line), at);
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
  Progress bar("terrainlod extract", cams.size(), progress_wanted(args.progress));
  for (std::size_t k = 0; k < cams.size(); ++k) {
    const std::size_t decoded0 = pyr.tiles_decoded(), bytes0 = pyr.bytes_touched();
    const Extraction x = extract_view(pyr, cams[k], args.z_exaggeration);
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
    Mesh mesh = tm ? tm->mesh : world_mesh(pyr, x.parts, extent);
    scale_heights(mesh, args.z_exaggeration);
    formats::store_output(frame_name(args.output, k, "-o"), formats::write_mesh(mesh, out.format), out.gzip);
    if (!args.png.empty()) write_output(frame_name(args.png, k, "--png"), render_png(mesh, cams[k], tm ? &textures : nullptr));
    for (auto it = texture_cache.begin(); it != texture_cache.end();) it = keep.count(it->first) ? std::next(it) : texture_cache.erase(it);
    frames.push_back({{"frame", k},
                      {"tiles", x.selection.tiles.size()},
                      {"tiles_per_level", tiles_per_level(pyr, x.selection)},
                      {"triangles", x.triangles},
                      {"hole_triangles", x.hole_triangles},
                      {"tiles_loaded", pyr.tiles_decoded() - decoded0},
                      {"bytes_loaded", pyr.bytes_touched() - bytes0},
                      {"tiles_evicted", evicted},
                      {"tiles_cached", pyr.tiles_cached()},
                      {"time_ms", {{"select_close", x.select_ms}, {"decode", x.decode_ms}}}});
    bar.advance();
  }
  bar.finish();
  if (!args.report.empty()) write_output(args.report, nlohmann::json({{"frames", frames}}).dump(2) + "\n");
  return 0;
}

}  // namespace

int run_extract(const ExtractArgs& args) {
  const auto out = mesh_output(args.output, args.to);
  if (args.tau < 0 || !std::isfinite(args.tau)) throw usage_error("--tau must be positive (got {})", args.tau);
  if (!args.path.empty()) return run_extract_path(args, out);
  if (!(args.z_exaggeration > 0) || !std::isfinite(args.z_exaggeration))
    throw usage_error("--z-exaggeration must be a positive number (got {})", args.z_exaggeration);
  terrainlod::Camera cam;
  const bool automatic = args.camera.empty();
  if (!automatic) {
    const std::string cam_name = is_stdio(args.camera) ? "-" : args.camera;
    const std::string camera_text = read_input(args.camera);
    nlohmann::json cj;
    try {
      cj = nlohmann::json::parse(camera_text);
    } catch (const nlohmann::json::parse_error& e) {
      throw bad_input("camera is not JSON: {} ({})", json_failure_words(e.what(), e.byte, camera_text), cam_name);
    } catch (const nlohmann::json::exception& e) {
      throw bad_input("camera is not JSON: {} ({})", json_failure_words(e.what(), 0, camera_text), cam_name);
    }
    cam = parse_camera(cj, cam_name);
  }
  const terrainlod::ViewDirection direction = terrainlod::camera_preset(args.camera_preset.empty() ? "overview" : args.camera_preset);
  PyramidFile pyr = open_pyramid(args.pyramid);
  if (!args.atlas.empty() && !pyr.textured()) throw usage_error("--atlas needs a pyramid with textures (build --texture)");
  // No --camera: the whole terrain (what this view draws: the DEM with --clip, else the
  // padded squares too) framed from the preset's side (docs/terrainlod.md §5).
  if (automatic) cam = terrainlod::frame_box(drawn_box(pyr, args.clip, args.z_exaggeration), direction, 1280, 800, 45, 0.04);
  if (args.tau > 0) cam.tau_px = args.tau;
  // One bar: the tiles decoded and triangulated, the mesh built (and the picture drawn),
  // the mesh coded and written; where each part ends as measured on a 2049^2 fBm pyramid
  // (1,024 tiles, 8.3 M triangles: 4-6 s decoding, 1.5-3 s mesh and picture, 0.3-1 s writing).
  Progress bar("terrainlod extract", 0, progress_wanted(args.progress));
  const double decoded_at = args.png.empty() ? 0.75 : 0.6, pictured_at = args.png.empty() ? 0.85 : 0.9;
  auto reached = [&bar](double f) { bar.set(static_cast<std::uint64_t>(1000 * f + 0.5), 1000); };
  const Extraction x = extract_view(pyr, cam, args.z_exaggeration, true, progress_part(bar.callback(), 0.0, decoded_at));
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
  if (tm) scale_heights(tm->mesh, args.z_exaggeration);
  Mesh mesh = tm ? tm->mesh : world_mesh(pyr, x.parts, extent);
  if (!tm) scale_heights(mesh, args.z_exaggeration);
  std::string png;
  if (!args.png.empty()) png = render_png(mesh, cam, tm ? &textures : nullptr);
  reached(pictured_at);
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
  bar.finish();
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
                        {"z_exaggeration", args.z_exaggeration},
                        {"camera", {{"automatic", automatic},
                                    {"eye", cam.eye},
                                    {"target", cam.target},
                                    {"up", cam.up},
                                    {"fovy_deg", cam.fovy_deg},
                                    {"width", cam.width},
                                    {"height", cam.height},
                                    {"near", cam.near},
                                    {"far", cam.far},
                                    {"tau_px", cam.tau_px}}},
                        {"time_ms", {{"select_close", x.select_ms}, {"decode", x.decode_ms}, {"write", ms_since(t2)}}}};
    if (pyr.nodata()) r["hole_triangles"] = x.hole_triangles;  // left out over nodata
    write_output(args.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::terrainlod_tool

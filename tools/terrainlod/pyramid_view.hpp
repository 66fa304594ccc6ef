#pragma once
// What decode, extract, verify and stats share: a pyramid opened, views of it selected
// and decoded (lib/terrainlod/extract), tiles welded into one world-space mesh, tile
// textures decoded, and the mesh output format settled from -o/--to.

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/progress_callback.hpp"
#include "core/mesh.hpp"
#include "formats/detect.hpp"
#include "pyramid_file.hpp"
#include "terrainlod/auto_camera.hpp"
#include "terrainlod/extract.hpp"

namespace fest::terrainlod_tool {

inline PyramidFile open_pyramid(const std::string& path) { return PyramidFile::open(path); }

// Level colours for the meshes and renderings (coarse = blue ... fine = red).
OpenMesh::Vec3uc level_colour(int level, int levels);

// --clip: triangles cut at the DEM's east and north edges (lib/terrainlod/dem_clip.hpp),
// so exactly the DEM rectangle is drawn and none of the pyramid's padding.
struct Extent {
  std::int64_t last_x = 0, last_y = 0;  // grid index of the last sample column and row
  bool clip = false;
  // Whether the triangle needs cutting (some vertex beyond the last column or row).
  bool crosses(const std::array<terrainlod::TileTriangulation::Vertex, 3>& v) const {
    return clip && (v[0].gx > last_x || v[1].gx > last_x || v[2].gx > last_x || v[0].gy > last_y || v[1].gy > last_y ||
                    v[2].gy > last_y);
  }
};
// The extent of the pyramid's DEM, clipping or not.
Extent extent_of(const PyramidFile& pyr, bool clip);

using Parts = std::vector<std::pair<terrainlod::TileId, terrainlod::TileTriangulation>>;

// Triangulations of several tiles -> one mesh in world coordinates; vertices shared by
// tiles (exactly equal grid position and height) become one vertex, so a crack-free
// selection gives a connected mesh. Faces coloured by level.
Mesh world_mesh(const PyramidFile& pyr, const Parts& parts, const Extent& extent = {});

// A tile's stored texture decoded to pixels (bad input naming the tile when it does not
// decode to T x T 8-bit pixels).
cv::Mat decode_texture(PyramidFile& pyr, const terrainlod::TileId& id);

// A camera from its JSON object (`where` names the file in messages).
terrainlod::Camera parse_camera(const nlohmann::json& j, const std::string& where);

struct Extraction {
  terrainlod::Selection selection;
  std::set<terrainlod::TileId> examined;  // tiles whose box the selection looked at
  std::vector<std::pair<terrainlod::TileId, terrainlod::TileTriangulation>> parts;
  std::size_t triangles = 0;       // drawn
  std::size_t hole_triangles = 0;  // not drawn: over nodata (a --nodata hole pyramid)
  double select_ms = 0, decode_ms = 0;
};

// The tiles a camera selects, closed, and their triangulations decoded. Heights drawn
// multiplied by z_scale (extract --z-exaggeration) cull with the boxes scaled alike. In a
// pyramid with holes the triangles over nodata are left out (lib/terrainlod/nodata_mask.hpp)
// unless `cut_holes` is false (verify looks at both sides of a hole's edge).
// `progress` hears the selected tiles decoded and triangulated.
Extraction extract_view(PyramidFile& pyr, const terrainlod::Camera& cam, double z_scale = 1, bool cut_holes = true,
                        const ProgressFn& progress = {});

// extract --z-exaggeration: every vertex height multiplied by k.
void scale_heights(Mesh& mesh, double k);

// The world box a view of the pyramid can draw: the DEM rectangle (clip) or the root
// tiles' squares (the padding included), with holes only the valid samples' part of it,
// heights over every tile (from the tile headers), times z_scale.
terrainlod::WorldBox drawn_box(PyramidFile& pyr, bool clip, double z_scale);

// The count of selected tiles per level, as a JSON array.
nlohmann::json tiles_per_level(const PyramidFile& pyr, const terrainlod::Selection& sel);

// Walking a pyramid root first (transmission order), once level l starts the tiles above
// it are needed only as parents of progressive tiles: drop every decoded tile but level
// l - 1's (keep_only keeps their ancestors), so memory holds about one level of tiles.
void keep_parents_only(PyramidFile& pyr, int level);

}  // namespace fest::terrainlod_tool

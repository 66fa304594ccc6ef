#pragma once
// Texture atlas (docs/brdffit.md §4; chapter 8 §8.6.3): triangles that share a flat
// parameterization (the same home image, or the same projection plane) are grouped into
// connected charts; each chart's texel rectangle, with a gutter of `gutter` texels on
// every side, is packed into one image by a shelf packer (charts sorted by height; the
// chapter cites Rocchini et al., any dense packer will do).
//
// Coordinates: texel units, texel (i, j) covers [i, i+1) x [j, j+1), its centre is
// (i + 0.5, j + 0.5); glTF's UV of a point is (x / width, y / height) (origin at the
// image's upper left corner). Charts are moved by whole texels only, so the sub-texel
// phase of the flat parameterization is kept (an atlas built from home-image pixels keeps
// the images' pixel centres).

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit {

// Per triangle: its group (charts never mix groups) and the texel coordinates of its three
// corners in that group's plane.
struct FlatTriangles {
  std::vector<std::uint32_t> group;
  std::vector<std::array<Eigen::Vector2d, 3>> corners;
};

struct AtlasOptions {
  int gutter = 2;     // texels around each chart; 2 keeps bilinear (and one mip level) inside
  int max_width = 0;  // atlas width; 0: about the square root of the charts' total area
};

struct AtlasChart {
  std::vector<std::uint32_t> triangles;
  int x = 0, y = 0, width = 0, height = 0;  // the rectangle in the atlas, gutter included
};

struct TextureAtlas {
  int width = 0, height = 0, gutter = 0;
  std::vector<AtlasChart> charts;
  std::vector<std::uint32_t> triangle_chart;              // per triangle
  std::vector<std::array<Eigen::Vector2d, 3>> corners;  // per triangle, atlas texel coordinates
  Eigen::Vector2d uv(std::size_t triangle, int corner) const {
    const Eigen::Vector2d& c = corners[triangle][static_cast<std::size_t>(corner)];
    return {c.x() / width, c.y() / height};
  }
};

// The flat parameterization of a mesh without images: every triangle goes to the group of
// the signed world axis its face normal is closest to (6 groups, as a cube map) and is
// projected orthographically onto that axis' plane at `texel_size` world units per texel.
// Throws bad_input for a non-positive texel size.
FlatTriangles axis_projection(const reflectance::TriangleMesh& mesh, double texel_size);

// The world-units-per-texel that makes the packed atlas about `side` texels wide: the
// mesh's area in the plane of its axis projection, spread over a fraction `fill` of side^2.
double texel_size_for(const reflectance::TriangleMesh& mesh, int side, double fill = 0.5);

// The texels the flat triangles cover (sum of their areas): a lower bound of the atlas'
// size, cheap to check before building one.
double flat_texel_area(const FlatTriangles& flat);

// Charts: connected (shared edge) triangles of one group, grown breadth-first; a triangle
// whose texel centres would land on texels another triangle of the chart already covers
// (a fold or overlap of the flat map) starts a chart of its own, so every texel centre
// belongs to at most one triangle. Throws bad_input when the sizes disagree with the mesh,
// a coordinate is not finite, or a chart is wider than options.max_width.
TextureAtlas build_atlas(const reflectance::TriangleMesh& mesh, const FlatTriangles& flat,
                         const AtlasOptions& options = {});

}  // namespace fest::brdffit

#pragma once
// A silhouette as runs of covered pixels per row (docs/brdffit.md §6): the coverage of
// rasterize_silhouette (the same pixel-centre rule, the same pixels), produced from the
// triangles' row spans without filling an image. Registration compares a rendered
// silhouette with a mask thousands of times; on runs the comparison costs the number of
// runs, not the number of pixels.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "reflectance/camera.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::reflectance {

struct PixelRun {
  std::int32_t begin, end;  // covered columns [begin, end)
};

struct CoverageRuns {
  int width = 0, height = 0;
  std::vector<std::uint32_t> row_begin;  // height + 1 offsets into `runs`
  std::vector<PixelRun> runs;            // per row ascending, disjoint, never touching
  std::size_t pixel_count() const;
};

// The mesh's silhouette seen by `camera` (its width and height): exactly the pixels
// rasterize_silhouette sets, for every thread count.
CoverageRuns silhouette_runs(const TriangleMesh& mesh, const PinholeCamera& camera, int threads = 1);

// The runs of the non-zero bytes of a row-major image with `stride` bytes per row.
CoverageRuns runs_of_mask(const std::uint8_t* data, int width, int height, std::size_t stride);

// Pixels covered by exactly one of `a` and `b` (the same width and height).
std::size_t symmetric_difference(const CoverageRuns& a, const CoverageRuns& b);

}  // namespace fest::reflectance

#include "reflectance/silhouette_runs.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "reflectance/triangle_scan.hpp"

namespace fest::reflectance {
namespace {

struct RowSpan {
  std::int32_t y, begin, end;  // [begin, end) of row y
};

// Rows [y0, y1) of the runs from the triangles' spans (in any order): spans bucketed by
// row, sorted by start and merged where they overlap or touch.
void merge_rows(std::vector<RowSpan>& spans, int y0, int y1, std::vector<std::uint32_t>& row_count,
                std::vector<PixelRun>& runs) {
  const std::size_t rows = static_cast<std::size_t>(y1 - y0);
  std::vector<std::uint32_t> start(rows + 1, 0);
  for (const RowSpan& s : spans) ++start[static_cast<std::size_t>(s.y - y0) + 1];
  for (std::size_t r = 0; r < rows; ++r) start[r + 1] += start[r];
  std::vector<PixelRun> sorted(spans.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const RowSpan& s : spans) sorted[fill[static_cast<std::size_t>(s.y - y0)]++] = {s.begin, s.end};
  }
  row_count.assign(rows, 0);
  runs.clear();
  for (std::size_t r = 0; r < rows; ++r) {
    const auto first = sorted.begin() + start[r], last = sorted.begin() + start[r + 1];
    std::sort(first, last, [](const PixelRun& a, const PixelRun& b) { return a.begin < b.begin; });
    const std::size_t before = runs.size();
    for (auto it = first; it != last; ++it) {
      if (runs.size() > before && it->begin <= runs.back().end)
        runs.back().end = std::max(runs.back().end, it->end);
      else
        runs.push_back(*it);
    }
    row_count[r] = static_cast<std::uint32_t>(runs.size() - before);
  }
}

}  // namespace

std::size_t CoverageRuns::pixel_count() const {
  std::size_t n = 0;
  for (const PixelRun& r : runs) n += static_cast<std::size_t>(r.end - r.begin);
  return n;
}

CoverageRuns silhouette_runs(const TriangleMesh& mesh, const PinholeCamera& camera, int threads) {
  CoverageRuns out;
  out.width = camera.width;
  out.height = camera.height;
  out.row_begin.assign(static_cast<std::size_t>(std::max(0, camera.height)) + 1, 0);
  if (camera.width <= 0 || camera.height <= 0) return out;
  const std::vector<scan::ScreenVertex> s = scan::project_vertices(mesh, camera);
  const int bands = band_count(camera.height, threads);
  std::vector<std::vector<std::uint32_t>> band_rows(static_cast<std::size_t>(bands));
  std::vector<std::vector<PixelRun>> band_runs(static_cast<std::size_t>(bands));
  parallel_bands_indexed(camera.height, threads, [&](int band, int y0, int y1) {
    std::vector<RowSpan> spans;
    std::size_t rows = 0;  // at most one span per row of a triangle's bounding box: no regrowth
    for (const auto& tri : mesh.triangles) {
      const double ymin = std::min({s[tri[0]].y, s[tri[1]].y, s[tri[2]].y});
      const double ymax = std::max({s[tri[0]].y, s[tri[1]].y, s[tri[2]].y});
      if (ymax >= y0 && ymin < y1) rows += static_cast<std::size_t>(std::min<double>(ymax, y1) - std::max<double>(ymin, y0)) + 1;
    }
    spans.reserve(rows);
    for (const auto& tri : mesh.triangles) {
      const scan::ScreenVertex &a = s[tri[0]], &b = s[tri[1]], &c = s[tri[2]];
      if (!scan::drawable(a, b, c)) continue;
      scan::scan_spans(a, b, c, camera.width, y0, y1, [&](int y, int x0, int x1) { spans.push_back({y, x0, x1 + 1}); });
    }
    merge_rows(spans, y0, y1, band_rows[static_cast<std::size_t>(band)], band_runs[static_cast<std::size_t>(band)]);
  });
  std::size_t row = 0;
  for (int k = 0; k < bands; ++k) {
    for (std::uint32_t n : band_rows[static_cast<std::size_t>(k)]) {
      out.row_begin[row + 1] = out.row_begin[row] + n;
      ++row;
    }
    out.runs.insert(out.runs.end(), band_runs[static_cast<std::size_t>(k)].begin(),
                    band_runs[static_cast<std::size_t>(k)].end());
  }
  return out;
}

CoverageRuns runs_of_mask(const std::uint8_t* data, int width, int height, std::size_t stride) {
  CoverageRuns out;
  out.width = width;
  out.height = height;
  out.row_begin.assign(static_cast<std::size_t>(std::max(0, height)) + 1, 0);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = data + static_cast<std::size_t>(y) * stride;
    for (int x = 0; x < width;) {
      if (!row[x]) {
        ++x;
        continue;
      }
      const int begin = x;
      while (x < width && row[x]) ++x;
      out.runs.push_back({begin, x});
    }
    out.row_begin[static_cast<std::size_t>(y) + 1] = static_cast<std::uint32_t>(out.runs.size());
  }
  return out;
}

std::size_t symmetric_difference(const CoverageRuns& a, const CoverageRuns& b) {
  if (a.width != b.width || a.height != b.height)
    throw bad_input("silhouettes of {}x{} and {}x{} pixels cannot be compared", a.width, a.height, b.width, b.height);
  // |A xor B| = |A| + |B| - 2 |A and B|, the intersection by a merge of the sorted runs.
  std::size_t common = 0;
  for (std::size_t y = 0; y < static_cast<std::size_t>(a.height); ++y) {
    std::uint32_t i = a.row_begin[y], j = b.row_begin[y];
    const std::uint32_t ie = a.row_begin[y + 1], je = b.row_begin[y + 1];
    while (i < ie && j < je) {
      const PixelRun &r = a.runs[i], &q = b.runs[j];
      const std::int32_t lo = std::max(r.begin, q.begin), hi = std::min(r.end, q.end);
      if (lo < hi) common += static_cast<std::size_t>(hi - lo);
      if (r.end < q.end)
        ++i;
      else
        ++j;
    }
  }
  return a.pixel_count() + b.pixel_count() - 2 * common;
}

}  // namespace fest::reflectance

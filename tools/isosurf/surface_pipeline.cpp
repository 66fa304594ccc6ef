// The pipeline of isosurf exact and adaptive: read, build the min-max pyramid, extract
// (full resolution, docs/isosurf.md section 2, or focus-adaptive, section 5), filter
// components, smooth, add normals, write the mesh and the report.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <nlohmann/json.hpp>

#include "surface_pipeline.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "isosurface/adaptive.hpp"
#include "isosurface/marching_cubes.hpp"
#include "isosurface/mesh_stats.hpp"
#include "isosurface/taubin_smooth.hpp"
#include "isosurface/vertex_normals.hpp"
#include "load_grid.hpp"
#include "surface_io.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

namespace fest::isosurf_tool {
namespace {

using Clock = SteadyClock;

// Keeps the `keep` largest components (by triangles; ties: the earlier one), vertices
// renumbered in their old order.
isosurface::Surface keep_largest(const isosurface::Surface& s, std::size_t keep) {
  std::vector<std::size_t> sizes;
  const auto label = isosurface::triangle_components(s, sizes);
  if (sizes.size() <= keep) return s;
  std::vector<std::uint32_t> order(sizes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return sizes[a] > sizes[b]; });
  std::vector<char> kept(sizes.size(), 0);
  for (std::size_t k = 0; k < keep; ++k) kept[order[k]] = 1;
  std::vector<std::uint32_t> remap(s.vertices(), UINT32_MAX);
  isosurface::Surface out;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    if (kept[label[t]])
      for (auto v : s.triangles[t]) remap[v] = 0;
  std::uint32_t n = 0;
  for (std::size_t v = 0; v < s.vertices(); ++v)
    if (remap[v] == 0) {
      remap[v] = n++;
      out.xyz.insert(out.xyz.end(), &s.xyz[3 * v], &s.xyz[3 * v] + 3);
    }
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    if (kept[label[t]]) out.triangles.push_back({remap[s.triangles[t][0]], remap[s.triangles[t][1]], remap[s.triangles[t][2]]});
  return out;
}

}  // namespace

int extract_surface(const ExactOptions& o, const AdaptiveArgs* ad) {
  const int threads = resolve_threads(o.threads);
  isosurface::ExtractOptions eo;
  eo.threads = threads;
  eo.face_rule = o.face_rule;
  eo.triangulation = o.tri;
  const std::size_t keep = o.keep_components;  // 0 = all
  const std::string format = output_format(o.to, o.output);
  if (o.normals && format == "stl") throw usage_error("--normals needs a format with vertex normals (ply, plya, obj, off or drc), not stl");

  // One bar over the stages; where each ends as measured on a 361x433x361 MRI (exact: the
  // read takes half of the time, writing a fifth; --smooth and --normals add their own).
  Progress bar(ad ? "isosurf adaptive" : "isosurf exact", 0, progress_wanted(o.progress));
  auto reached = [&bar](double f) { bar.set(static_cast<std::uint64_t>(1000 * f + 0.5), 1000); };
  auto t0 = Clock::now();
  const LoadedGrid in = load_grid(o);
  reached(0.45);
  const double t_read = seconds_since(t0);
  t0 = Clock::now();
  std::optional<volume_pyramid::MinMaxPyramid> pyramid;
  if (!o.no_octree) pyramid.emplace(in.grid, threads);
  const double t_build = seconds_since(t0);
  reached(0.5);
  t0 = Clock::now();
  eo.progress = progress_part(bar.callback(), 0.5, 0.75);
  isosurface::ExtractStats es;
  isosurface::Surface s;
  isosurface::AdaptiveResult ar;
  if (ad) {
    isosurface::AdaptiveOptions ao;
    // (--cap pads around the grid without moving world or --index-space coordinates)
    ao.focus = ad->focus;
    if (!(ad->max_error >= 0)) throw usage_error("--max-error takes a value >= 0 or inf");
    ao.max_error = ad->max_error;
    if (ad->focus_radius < 0) throw usage_error("--focus-radius must be positive");
    ao.focus_radius = ad->focus_radius;
    ao.error_growth = ad->error_growth;
    ao.max_level = ad->max_level;
    ao.edge_rule = ad->edge_rule;
    ao.face_rule = eo.face_rule;
    ao.triangulation = eo.triangulation;
    ao.threads = threads;
    if (!pyramid) pyramid.emplace(in.grid, threads);
    ar = isosurface::extract_adaptive(in.grid, in.iso, ao, *pyramid);
    s = std::move(ar.surface);
    es.centroid_vertices = ar.centroid_vertices;
  } else {
    s = isosurface::extract_isosurface(in.grid, in.iso, eo, pyramid ? &*pyramid : nullptr, &es);
  }
  reached(0.75);
  if (keep) s = keep_largest(s, keep);
  isosurface::taubin_smooth(s, o.smooth);
  if (o.normals) isosurface::add_gradient_normals(in.grid, s, threads);
  reached(0.8);
  const double t_extract = seconds_since(t0);
  if (s.triangles.empty() && !o.quiet)
    warn("isosurf", fmt::format("no surface: iso {} is outside the data range [{}, {}] or never crossed ({})", in.iso,
                                in.data_min, in.data_max, in.source));
  t0 = Clock::now();
  const std::string bytes = encode_surface(s, format, o.qbits);
  write_output(o.output, bytes);
  bar.finish();
  const double t_write = seconds_since(t0);
  if (!o.report.empty()) {
    auto j = stats_json(isosurface::mesh_stats(s, threads));
    j["iso"] = in.iso;
    j["mode"] = ad ? "adaptive" : "exact";
    if (ad) {
      j["leaves_per_level"] = ar.leaves_per_level;
      j["edge_rule"] = ad->edge_rule == isosurface::EdgeRule::all ? "all" : "transitions";
      j["closure_splits"] = ar.closure_splits;
      j["max_error_bound"] = ar.max_error_bound;
    }
    j["source"] = in.source;
    j["centroid_vertices"] = es.centroid_vertices;
    j["cells_visited"] = es.cells_visited;
    j["blocks_active"] = es.blocks_active;
    j["blocks_total"] = es.blocks_total;
    j["pyramid_bytes"] = pyramid ? pyramid->bytes() : 0;
    j["time_s"] = {{"read", t_read}, {"build", t_build}, {"extract", t_extract}, {"write", t_write}};
    write_output(o.report, j.dump(2) + "\n");
  }
  return 0;
}


}  // namespace fest::isosurf_tool

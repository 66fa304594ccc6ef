#include "load_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"

namespace fest::isosurf_tool {
namespace {

// --roi i0,i1,j0,j1,k0,k1: keeps the samples of the inclusive index box; world positions
// stay (the origin moves to the box's first sample, returned in `first`). Returns the NaN
// samples kept.
std::size_t crop(volume_pyramid::ScalarGrid& g, const std::array<long long, 6>& r, double first[3]) {
  for (int a = 0; a < 3; ++a)
    if (r[2 * a] < 0 || r[2 * a] >= r[2 * a + 1] || r[2 * a + 1] >= static_cast<long long>(g.dims[a]))
      throw usage_error("--roi {},{},{},{},{},{} is not inside the {}x{}x{} volume with at least 2 samples per axis", r[0], r[1], r[2],
                        r[3], r[4], r[5], g.dims[0], g.dims[1], g.dims[2]);
  volume_pyramid::ScalarGrid c;
  for (int a = 0; a < 3; ++a) c.dims[a] = std::size_t(r[2 * a + 1] - r[2 * a] + 1);
  c.axes = g.axes;
  c.origin = g.world(double(r[0]), double(r[2]), double(r[4]));
  c.values.resize(c.size());
  std::size_t nans = 0;
  for (std::size_t k = 0; k < c.dims[2]; ++k)
    for (std::size_t j = 0; j < c.dims[1]; ++j)
      for (std::size_t i = 0; i < c.dims[0]; ++i) {
        const float x = g.at(i + std::size_t(r[0]), j + std::size_t(r[2]), k + std::size_t(r[4]));
        nans += std::isnan(x);
        c.values[c.index(i, j, k)] = x;
      }
  g = std::move(c);
  for (int a = 0; a < 3; ++a) first[a] = double(r[2 * a]);
  return nans;
}

}  // namespace

LoadedGrid load_grid(const ExactOptions& o) {
  if (!o.iso && o.labels.empty()) throw usage_error("give --iso VALUE or --label K[,K...]");
  if (o.iso && !o.labels.empty()) throw usage_error("--iso and --label exclude each other");
  if (o.iso && !std::isfinite(*o.iso)) throw usage_error("--iso must be a finite number");
  LoadedGrid out;
  out.source = input_name(o.input);
  formats::VolumeSourceOptions vo;
  vo.field = o.field;
  vo.component = o.component;
  vo.frame = o.frame;
  vo.raw = o.raw;
  formats::Input in = formats::load_volume_input(o.input, vo);
  if (in.bytes.empty()) throw bad_input("empty input ({})", out.source);
  const Volume v = formats::read_volume_source(in, vo);
  for (int a = 0; a < 3; ++a)
    if (v.dims[a] < 2)
      throw bad_input("volume is {}x{}x{}: isosurfaces need at least 2 samples along every axis; use a 2-D contouring tool ({})",
                      v.dims[0], v.dims[1], v.dims[2], out.source);
  std::size_t nans = 0;
  out.grid = volume_pyramid::to_grid(v, nans);
  double roi_lo[3] = {0, 0, 0};  // the ROI's first sample (for --index-space)
  if (o.roi) nans = crop(out.grid, *o.roi, roi_lo);
  auto& values = out.grid.values;
  if (nans > 0) {
    if (!o.nan_outside)
      throw bad_input("{} NaN samples; --nan-outside treats them as outside ({})", nans, out.source);
  }
  if (!o.labels.empty()) {
    const std::set<long> keep(o.labels.begin(), o.labels.end());
    for (auto& x : values) x = !std::isnan(x) && keep.count(std::lround(x)) && x == std::round(x) ? 1.0f : 0.0f;
    out.iso = 0.5f;
  } else {
    out.iso = static_cast<float>(*o.iso);
  }
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (float x : values)
    if (!std::isnan(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  if (!(lo <= hi)) lo = hi = 0;  // every sample NaN
  out.data_min = lo, out.data_max = hi;
  // NaN -> below everything: outside, whatever iso is.
  if (nans > 0)
    for (auto& x : values)
      if (std::isnan(x)) x = std::min(lo, out.iso) - 1.0f;
  if (o.index_space) {  // voxel coordinates of the whole volume, also inside a --roi
    out.grid.origin = {0, 0, 0};
    out.grid.axes = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (o.roi) out.grid.origin = {double(roi_lo[0]), double(roi_lo[1]), double(roi_lo[2])};
  }
  if (o.cap) {
    const double cap = o.cap_value ? *o.cap_value : static_cast<double>(std::min(lo, out.iso)) - 1.0;
    if (!std::isfinite(cap)) throw usage_error("--cap must be a finite number");
    out.grid = volume_pyramid::padded(out.grid, static_cast<float>(cap));
  }
  return out;
}

}  // namespace fest::isosurf_tool

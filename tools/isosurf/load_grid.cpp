#include "load_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"

namespace fest::isosurf {

LoadedGrid load_grid(const ExactOptions& o) {
  if (!o.iso && o.labels.empty()) throw usage_error("give --iso VALUE or --label K[,K...]");
  if (o.iso && !o.labels.empty()) throw usage_error("--iso and --label exclude each other");
  if (o.iso && !std::isfinite(*o.iso)) throw usage_error("--iso must be a finite number");
  LoadedGrid out;
  out.source = o.input == "-" ? "stdin" : o.input;
  formats::Input in = formats::load_input(o.input);
  if (in.bytes.empty()) throw bad_input("empty input ({})", out.source);
  formats::VolumeSourceOptions vo;
  vo.field = o.field;
  vo.component = o.component;
  vo.frame = o.frame;
  const Volume v = formats::read_volume_source(in, vo);
  for (int a = 0; a < 3; ++a)
    if (v.dims[a] < 2)
      throw bad_input("volume is {}x{}x{}: isosurfaces need at least 2 samples along every axis; use a 2-D contouring tool ({})",
                      v.dims[0], v.dims[1], v.dims[2], out.source);
  std::size_t nans = 0;
  out.grid = volume_pyramid::to_grid(v, nans);
  auto& values = out.grid.values;
  if (nans > 0) {
    if (!o.nan_outside)
      throw bad_input("{} NaN samples; --nan-outside treats them as outside ({})", nans, out.source);
  }
  if (!o.labels.empty()) {
    std::set<long> keep;
    std::stringstream ss(o.labels);
    for (std::string item; std::getline(ss, item, ',');) {
      char* end = nullptr;
      const long k = std::strtol(item.c_str(), &end, 10);
      if (item.empty() || *end) throw usage_error("--label takes integers separated by commas, not '{}'", o.labels);
      keep.insert(k);
    }
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
  if (o.index_space) {
    out.grid.origin = {0, 0, 0};
    out.grid.axes = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  }
  if (o.cap) {
    const double cap = o.cap_value ? *o.cap_value : static_cast<double>(std::min(lo, out.iso)) - 1.0;
    if (!std::isfinite(cap)) throw usage_error("--cap must be a finite number");
    out.grid = volume_pyramid::padded(out.grid, static_cast<float>(cap));
  }
  return out;
}

}  // namespace fest::isosurf

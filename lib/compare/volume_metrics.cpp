#include <cmath>
#include <limits>

#include "compare/volume_compare.hpp"
#include "core/error.hpp"

namespace fest::compare {

VolumeError volume_error(const Volume& a, const Volume& b, std::size_t max_labels) {
  if (a.dims != b.dims)
    throw runtime_failure("volume dimensions differ: {}x{}x{} and {}x{}x{}", a.dims[0], a.dims[1], a.dims[2],
                          b.dims[0], b.dims[1], b.dims[2]);
  if (a.frames != b.frames || a.voxels.size() != b.voxels.size())
    throw runtime_failure("volume frame counts differ: {} and {} frames of {}x{}x{}", a.frames, b.frames, a.dims[0],
                          a.dims[1], a.dims[2]);
  VolumeError e;
  for (int i = 0; i < 3; ++i) {
    e.max_spacing_diff = std::max(e.max_spacing_diff, std::abs(a.spacing[i] - b.spacing[i]));
    e.max_origin_diff = std::max(e.max_origin_diff, std::abs(a.origin[i] - b.origin[i]));
  }
  double sum_sq = 0;
  const std::size_t n = a.voxels.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double x = a.voxels[i], y = b.voxels[i];
    double diff;
    if (std::isnan(x) || std::isnan(y))
      diff = (std::isnan(x) && std::isnan(y)) ? 0.0 : std::numeric_limits<double>::infinity();
    else
      diff = std::abs(x - y);
    e.max_abs = std::max(e.max_abs, diff);
    sum_sq += diff * diff;
  }
  e.rmse = n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;

  if (!scalar_type_is_integer(a.type) || !scalar_type_is_integer(b.type)) return e;
  struct Counts {
    std::size_t in_a = 0, in_b = 0, both = 0;
  };
  std::map<long long, Counts> counts;
  for (std::size_t i = 0; i < n; ++i) {
    const long long la = std::llround(a.voxels[i]), lb = std::llround(b.voxels[i]);
    if (la != 0) ++counts[la].in_a;
    if (lb != 0) ++counts[lb].in_b;
    if (la == lb && la != 0) ++counts[la].both;
    if (counts.size() > max_labels) return e;  // an intensity image, not a label map
  }
  e.labels = true;
  for (const auto& [label, c] : counts) {
    const double dice = 2.0 * static_cast<double>(c.both) / static_cast<double>(c.in_a + c.in_b);
    e.dice[label] = dice;
    e.min_dice = std::min(e.min_dice, dice);
  }
  return e;
}

}  // namespace fest::compare

#pragma once
// Volume differences: value statistics and, for label volumes, Dice overlap per label.

#include <map>
#include <vector>

#include "core/volume.hpp"

namespace fest::compare {

struct VolumeError {
  double max_abs = 0;
  double rmse = 0;
  double max_spacing_diff = 0;  // largest |spacing_a - spacing_b| over the axes (mm)
  double max_origin_diff = 0;   // largest |origin_a - origin_b| over the axes (mm)
  // Dice = 2|A∩B| / (|A|+|B|) per non-zero label, when both volumes hold integers.
  std::map<long long, double> dice;
  double min_dice = 1;  // over `dice`; 1 when there are no labels
  bool labels = false;  // whether dice was computed
};

// Same dimensions required (throws Status::failure otherwise). Dice is computed when
// both volumes have integer value types and at most `max_labels` distinct values.
VolumeError volume_error(const Volume& a, const Volume& b, std::size_t max_labels = 1024);

}  // namespace fest::compare

#pragma once
// Previews of a field (fluidsim(1)): a slice, a maximum-intensity projection,
// or the emission-absorption integral along an axis,
//   I = sum_k c s_k exp(-sigma h sum_(j<k) s_j),  c = sigma h (so I stays below 1),
// and the colour maps that turn the result into RGB.

#include <array>
#include <vector>

namespace fest::fluidsim {

enum class RenderMode { slice, mip, absorb };

struct RenderOptions {
  RenderMode mode = RenderMode::absorb;
  int axis = 2;       // viewing axis (2-D frames: ignored)
  int index = -1;     // slice index, -1: the middle
  double sigma = 1.0; // absorb: extinction per unit of field per unit length
  double spacing = 1.0;
};

// A float image, row 0 at the top (the image's "up" is the highest coordinate of the
// second remaining axis).
struct Plane {
  int width = 0, height = 0;
  std::vector<double> values;
};

// Throws Status::usage for an axis or slice index out of range.
Plane render_plane(const std::vector<double>& field, const std::array<int, 3>& size, int dim,
                   const RenderOptions& options);

enum class Colormap { gray, inferno, velocity };

// Maps t in [0, 1] (clamped) to RGB in [0, 1]: gray, inferno or velocity (a
// blue-white-red diverging map centred on 0.5).
std::array<double, 3> colour(Colormap map, double t);

}  // namespace fest::fluidsim

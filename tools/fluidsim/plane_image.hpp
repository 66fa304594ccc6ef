#pragma once
// A rendered plane (lib/fluidsim/render.hpp) as an image: 8/16-bit RGB through a colour
// map, or one float channel. Shared by run (PNG previews) and render.

#include <opencv2/core.hpp>

#include "fluidsim/render.hpp"

namespace fest::fluidsim_tool {

// Values lo..hi map to the ends of the colour map; depth is 8 or 16 bits per channel.
cv::Mat plane_to_rgb(const fluidsim::Plane& plane, double lo, double hi, fluidsim::Colormap map, int depth);
cv::Mat plane_to_float(const fluidsim::Plane& plane);

}  // namespace fest::fluidsim_tool

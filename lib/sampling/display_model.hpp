#pragma once
// Display reconstruction models of `resample display` (docs/resample.md "Display reconstruction", §10.4.3): the point
// response r with which a display turns samples into the continuous image the viewer sees.

#include <string>

#include "sampling/kernel.hpp"

namespace fest::sampling {

struct DisplayModel {
  Kernel x, y;  // separable point response along each axis
};

// "lcd" (box), "tent", "bspline", "gaussian:sigma=S", or "crt[:sx=0.45,sy=0.35]": a
// horizontal sample-and-hold box convolved with a Gaussian spot of σx along x, the spot
// of σy along y (Fig. 10.9: the spot spreads more horizontally). Others: usage error.
DisplayModel make_display_model(const std::string& spec);

// The hold box of width 1 convolved with a Gaussian of σ: ½[erf((x+½)/(σ√2)) − erf((x−½)/(σ√2))].
double box_gaussian(double sigma, double x);

}  // namespace fest::sampling

#pragma once
// Analytic test scenes of `resample render` (docs/resample.md "Rendering analytic scenes"): continuous functions of screen
// position (x, y) in output pixels (origin at the top-left corner, pixel (i, j) covering
// [i, i+1) × [j, j+1)), with values in linear [0, 1].

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sampling/kernel.hpp"

namespace fest::sampling {

struct Scene {
  std::string name;
  std::function<double(double x, double y)> value;
  // The `point` scene is rendered analytically through the pixel filter (Fig. 10.7) and
  // is not supersampled: then `analytic` is true and `value` already includes the filter.
  bool analytic = false;
};

// Builds a scene for an image of width × height pixels from "--param key=value" pairs.
// Unknown scenes and keys are usage errors naming what is accepted.
//   zoneplate: numax (1.0)                  ½ + ½ cos(π numax r² / R), R = width / 2
//   sine:      f (0.1), phase (0), angle (0, degrees), f2 (none: a single grating)
//   siemens:   spokes (64)
//   edges:     cx, cy, radius (32.17, 31.61, 20.3), angle (23°), offset (40 (cos + sin))
//   point:     w (1), x0, y0 (centre), zoom (8); `filter` is the pixel filter, or the
//              radial "lowpass" / "bandpass" (lo = 0.2) of docs/resample.md "Rendering analytic scenes"
Scene make_scene(const std::string& name, const std::map<std::string, double>& params, int width, int height,
                 const std::string& point_filter = "lowpass");

// The names make_scene accepts.
std::vector<std::string> scene_names();

// Zone-plate local frequency ν(r) = numax · r / R at a pixel centre (cycles per pixel).
double zoneplate_frequency(double numax, int width, int height, int i, int j);

// The ideal (unfiltered) zone plate at a pixel centre.
double zoneplate_value(double numax, int width, int height, double x, double y);

}  // namespace fest::sampling

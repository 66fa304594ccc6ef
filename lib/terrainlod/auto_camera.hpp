#pragma once
// extract without --camera (docs/terrainlod.md §5, automatic camera): a camera that frames
// a box (the terrain's extent and height range) from a named direction so that the box
// fills the view and every point of it projects inside the image.

#include <string>
#include <vector>

#include "terrainlod/extract.hpp"

namespace fest::terrainlod {

struct WorldBox {
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
};

// Where the camera looks from: the eye's direction from the box centre as an azimuth
// (degrees clockwise from north: 0 = from the north, 90 = from the east) and an elevation
// above the horizon (90 = straight down, north up in the image).
struct ViewDirection {
  double azimuth_deg = 225, elevation_deg = 35;
};

// The named presets: overview (from the south-west, 35 deg), oblique (south-west, 20 deg),
// north, south, east, west (from that side, 30 deg), top (straight down). Throws
// usage_error naming the allowed words for anything else.
ViewDirection camera_preset(const std::string& name);
const std::vector<std::string>& camera_preset_names();

// The camera looking at the box centre from `dir` whose frustum holds all 8 corners of
// the box with `margin` (fraction of the half-width/height kept free, 0..1) and touches
// the box (the nearest distance that holds it). width x height pixels, vertical field of
// view fovy_deg; near/far bracket the box.
Camera frame_box(const WorldBox& box, const ViewDirection& dir, int width, int height, double fovy_deg, double margin);

}  // namespace fest::terrainlod

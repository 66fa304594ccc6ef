#pragma once
// The typed camera options (--size, --view, --eye, --screen, --mirror, --stereo) -> cameras
// (lib/raycast).

#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "raycast/camera.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::volrender_tool {

// The camera(s): one, or two (left, right) with --stereo. `grid` gives the bounds for
// orbit cameras. Throws usage errors for degenerate geometry.
std::vector<raycast::Camera> make_cameras(const CameraArgs& a, const volume_pyramid::ScalarGrid* grid);

nlohmann::json camera_json(const raycast::Camera& c);

}  // namespace fest::volrender_tool

#pragma once
// --size/--view/--eye/--screen/--mirror/--stereo strings -> cameras (lib/raycast).

#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "raycast/camera.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::volrender {

std::pair<int, int> parse_size(const std::string& s);
std::vector<double> parse_numbers(const std::string& s, std::size_t min, std::size_t max, const char* flag);

// The camera(s): one, or two (left, right) with --stereo. `grid` gives the bounds for
// orbit cameras. Throws usage errors for degenerate geometry.
std::vector<raycast::Camera> make_cameras(const CameraArgs& a, const volume_pyramid::ScalarGrid* grid);

nlohmann::json camera_json(const raycast::Camera& c);

}  // namespace fest::volrender

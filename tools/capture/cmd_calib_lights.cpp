// capture calib-lights (docs/capture.md §5): light positions from chrome spheres
// (lib/capture/calib_lights) -> lights_cal.json on stdout.

#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "calib_images.hpp"
#include "capture/calib_lights.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace fest::capture_tool {

using nlohmann::json;
using namespace fest::capture;

int calib_lights_command(const CalibLightsOptions& a) {
  if (!(a.ball_radius > 0)) throw usage_error("--ball-radius must be a positive length in mm");
  const Intrinsics cam = read_camera(a.camera);
  std::vector<SphereRay> rays;
  json spheres = json::array();
  std::vector<std::string> used, missing;
  for (const std::string& path : a.images) {
    const GreyImage g = read_grey(path);
    check_camera_size(cam, g.grey, a.camera, path);
    const std::vector<SphereImage> found = detect_spheres(g.grey);
    if (found.empty()) {
      missing.push_back(path);
      continue;
    }
    used.push_back(path);
    for (const SphereImage& s : found) {
      rays.push_back(sphere_ray(s, cam, a.ball_radius));
      spheres.push_back({{"image", path},
                         {"outline_centre_px", json::array({s.centre.x, s.centre.y})},
                         {"outline_radius_px", s.radius},
                         {"highlight_px", json::array({s.highlight.x, s.highlight.y})},
                         {"centre_mm", json_array(rays.back().centre)}});
    }
  }
  if (rays.empty()) throw bad_input("no chrome sphere with a highlight found in any image: {}", joined(missing));
  for (const std::string& m : missing) note(a.quiet, fmt::format("no sphere with a highlight found; image left out ({})", m));
  const LightFit fit = triangulate_light(rays);
  for (std::size_t i = 0; i < rays.size(); ++i) spheres[i]["ray_distance_mm"] = fit.ray_distance_mm[i];
  json doc = {{"lights", json::array({{{"id", a.id}, {"position", json_array(fit.position)}, {"residual_mm", fit.residual_rms_mm}, {"rays", rays.size()}}})},
              {"ball_radius_mm", a.ball_radius},
              {"camera", a.camera},
              {"spheres", spheres},
              {"images", used},
              {"left_out", missing}};
  emit(doc);
  return 0;
}

}  // namespace fest::capture_tool

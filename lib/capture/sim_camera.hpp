#pragma once
// The simulated camera (camera URI `sim:` or `sim:scene.json`, docs/capture.md §4.2):
// it ray-casts an analytic object -- a sphere on the turntable, one Lafortune
// material or two (one per hemisphere, split by the plane x_T = 0 through its centre) --
// on a black background, at the table's current angle, lit by the point lights that are
// on (radiance L = f_r(u, v) I cos(theta_i) / d^2, d in metres), with a backlight
// (role "backlight") filling the background for silhouettes. The radiance is exposed
// through a known response (gamma with a linear toe and a soft shoulder) plus read noise:
//
//   X = gain L t;   v = X^(1/gamma) for X >= toe, X toe^(1/gamma - 1) below (linear toe);
//   above v = shoulder the curve rolls off exponentially towards 1 (C1, never clips);
//   Z = round(black + (2^bits - 1 - black) v + n),  n ~ N(0, noise_dn^2),  clamped.
//
// Deterministic: the picture is a function of the table position, the lights on and the
// exposure time only (the noise seed is derived from them), so a resumed session
// re-creates the very bytes of an uninterrupted one.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "capture/camera.hpp"
#include "capture/light_bank.hpp"
#include "capture/station.hpp"
#include "capture/turntable.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::capture {

struct SimResponse {
  int bits = 16;
  double gamma = 2.2;
  double toe = 0.002;     // X below this is linear
  double shoulder = 0.8;  // v above this rolls off towards 1
  double black_level = 0;  // DN
  double noise_dn = 64;    // DN of this bit depth (64 of 65535 = 0.25 of 255)
  // v(X) in [0, 1) and the DN without noise.
  double curve(double x) const;
  double dn(double x) const;
};

struct SimScene {
  int width = 640, height = 480;
  std::array<double, 3> centre_mm{0, 0, 50};  // in the turntable frame T
  double radius_mm = 50;
  std::vector<reflectance::LafortuneBrdf> materials;  // 1 or 2
  double gain = 100;                // X = gain L t
  double backlight_radiance = 100;  // background radiance per unit backlight intensity
  SimResponse response;
  std::uint64_t seed = 1;
};

// Defaults: the sphere above, pbrt's clay on x_T >= 0 and a blue glossy material
// (rho_d 0.1 0.15 0.5, one mirror lobe Cxy = -1, Cz = 1, N = 30) on the other half.
SimScene default_sim_scene();
// scene.json: {"width", "height", "object": {"centre_mm", "radius_mm", "materials": [brdf.json...]},
// "gain", "backlight_radiance", "response": {"bits", "gamma", "toe", "shoulder", "black_level",
// "noise_dn"}, "seed"}; absent keys keep the defaults. Throws bad_input naming where and path.
SimScene parse_sim_scene(const nlohmann::json& doc, const std::string& where);
// brdf.json of brdffit(1) ({"model":"lafortune","rho_d":[3],"Cxy":[[3]],"Cz":[[3]],"N":[[3]]}).
reflectance::LafortuneBrdf parse_lafortune(const nlohmann::json& doc, const std::string& where, const std::string& path);

// The object as seen at table angle theta (degrees, the angle the table really is at),
// radiance per pixel (CV_32FC3, R,G,B) with the given lights on. Ids not in the station,
// and lights without position_mm, are bad_input.
cv::Mat render_sim_radiance(const SimScene& scene, const CameraIntrinsics& intrinsics, const TurntableCal& cal,
                            double theta_deg, const Station& station, const std::vector<std::string>& lights_on);

class SimCamera : public Camera {
 public:
  // The intrinsics' size wins over the scene's. The table and lights are read at every
  // capture (a SimTurntable's true table position, which includes gear backlash).
  SimCamera(SimScene scene, CameraIntrinsics intrinsics, TurntableCal cal, Station station, Turntable& table,
            LightBank& lights);
  CameraInfo info() override;
  void set_exposure(double seconds) override;
  Image capture() override;
  void set_repeat_index(int take) override { take_ = take; }

  // Exposure of a radiance image as this camera does it (for tests and selftest).
  cv::Mat expose(const cv::Mat& radiance, double seconds, std::uint64_t seed) const;

 private:
  double table_angle_deg();
  SimScene scene_;
  CameraIntrinsics intrinsics_;
  TurntableCal cal_;
  Station station_;
  Turntable& table_;
  LightBank& lights_;
  std::uint32_t steps_per_rev_ = 0;
  double exposure_s_ = 0.01;
  int take_ = 0;
  // The last rendering, keyed by table position and lights on: an exposure series
  // re-exposes it instead of ray-casting again.
  std::string cache_key_;
  cv::Mat cache_;
};

}  // namespace fest::capture

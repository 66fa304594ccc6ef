// The simulated camera's radiometry against closed forms (docs/capture.md §6): a
// sphere straight ahead of the camera, lit by a point light at the camera centre, seen
// at its front point where n = u = v; L = f_r I cos / d^2 with f_r = rho_d / pi + Cz^N
// there (ux vx + uy vy = 0, uz vz = 1), and the response's DN of gain L t.

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "capture/sim_camera.hpp"
#include "capture/sim_lights.hpp"
#include "capture/sim_turntable.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;

struct Rig {
  SimScene scene;
  CameraIntrinsics k;
  TurntableCal cal;
  Station station;
  Rig() {
    scene = default_sim_scene();
    scene.centre_mm = {0, 0, 0};
    scene.radius_mm = 50;
    fest::reflectance::LafortuneBrdf m;
    m.rho_d = fest::reflectance::Rgb(0.2, 0.4, 0.6);
    fest::reflectance::LafortuneLobe lobe;
    lobe.cxy = fest::reflectance::Rgb::Constant(-0.9);
    lobe.cz = fest::reflectance::Rgb::Constant(0.9);
    lobe.n = fest::reflectance::Rgb::Constant(10);
    m.lobes = {lobe};
    scene.materials = {m};
    scene.response.noise_dn = 0;
    k.K = {100, 0, 40, 0, 100, 30, 0, 0, 1};  // the sphere spans about 20 px
    k.width = 81;
    k.height = 61;
    cal.R_T0 = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    cal.t_T0 = {0, 0, 500};  // sphere centre 500 mm ahead, front point at 450 mm
    LightConfig l;
    l.id = "L0";
    l.uri = "sim:";
    l.position_mm = std::array<double, 3>{0, 0, 0};
    l.intensity = {1, 2, 0.5};
    LightConfig bg;
    bg.id = "BG";
    bg.uri = "sim:";
    bg.role = "backlight";
    bg.intensity = {1, 1, 1};
    station.lights = {l, bg};
  }
};

TEST(CaptureSimCamera, FrontPointRadianceIsClosedForm) {
  const Rig rig;
  const cv::Mat r = render_sim_radiance(rig.scene, rig.k, rig.cal, 0.0, rig.station, {"L0"});
  const cv::Vec3f at = r.at<cv::Vec3f>(30, 40);
  const double d = 0.450;  // metres
  const double rho[3] = {0.2, 0.4, 0.6}, intensity[3] = {1, 2, 0.5};
  for (int c = 0; c < 3; ++c) {
    const double expected = (rho[c] / M_PI + std::pow(0.9, 10)) * intensity[c] / (d * d);
    EXPECT_NEAR(at[c], expected, 1e-5 * expected) << c;
  }
  // The rotation about the table axis through the centre leaves the front point alone.
  const cv::Mat turned = render_sim_radiance(rig.scene, rig.k, rig.cal, 37.0, rig.station, {"L0"});
  EXPECT_NEAR(turned.at<cv::Vec3f>(30, 40)[1], at[1], 1e-4 * at[1]);
  // Background: black without the backlight, backlight_radiance x intensity with it.
  EXPECT_EQ(r.at<cv::Vec3f>(0, 0)[0], 0.0f);
  const cv::Mat lit = render_sim_radiance(rig.scene, rig.k, rig.cal, 0.0, rig.station, {"BG"});
  EXPECT_FLOAT_EQ(lit.at<cv::Vec3f>(0, 0)[2], float(rig.scene.backlight_radiance));
  // The backlight does not light the object (it is behind it).
  EXPECT_EQ(lit.at<cv::Vec3f>(30, 40)[0], 0.0f);
}

TEST(CaptureSimCamera, ResponseIsGammaWithToeAndShoulder) {
  SimResponse r;
  EXPECT_NEAR(r.curve(0.5), std::pow(0.5, 1 / 2.2), 1e-12);
  // Linear toe, continuous at the toe point.
  EXPECT_NEAR(r.curve(r.toe / 2), std::pow(r.toe, 1 / 2.2) / 2, 1e-12);
  EXPECT_NEAR(r.curve(r.toe * (1 - 1e-9)), r.curve(r.toe), 1e-8);
  // Shoulder: continuous, increasing, below 1.
  const double x_s = std::pow(r.shoulder, 2.2);
  EXPECT_NEAR(r.curve(x_s * (1 + 1e-9)), r.shoulder, 1e-8);
  EXPECT_LT(r.curve(10), 1.0);
  double last = 0;
  for (double x = 1e-5; x < 50; x *= 1.1) {
    EXPECT_GT(r.curve(x), last);
    last = r.curve(x);
  }
}

TEST(CaptureSimCamera, CaptureExposesTheFrontPointAndIsDeterministic) {
  const Rig rig;
  SimTurntable table(SimTurntableConfig{});
  SimLightBank lights({"L0", "BG"});
  SimCamera camera(rig.scene, rig.k, rig.cal, rig.station, table, lights);
  lights.set("L0", true);
  const double t = 0.004;
  camera.set_exposure(t);
  const fest::Image a = camera.capture();
  ASSERT_EQ(a.pixels.type(), CV_16UC3);
  const double d = 0.450;
  const double L = (0.4 / M_PI + std::pow(0.9, 10)) * 2 / (d * d);  // green
  const double expected = std::round(65535 * rig.scene.response.curve(rig.scene.gain * L * t));
  EXPECT_NEAR(a.pixels.at<cv::Vec3w>(30, 40)[1], expected, 1.0);  // float radiance: +-1 DN

  // With noise, the same state gives the same bytes, another exposure other bytes.
  Rig noisy;
  noisy.scene.response.noise_dn = 64;
  SimCamera cam2(noisy.scene, noisy.k, noisy.cal, noisy.station, table, lights);
  cam2.set_exposure(t);
  const cv::Mat x = cam2.capture().pixels, y = cam2.capture().pixels;
  EXPECT_EQ(cv::norm(x, y, cv::NORM_INF), 0.0);
  cam2.set_exposure(2 * t);
  EXPECT_GT(cv::norm(x, cam2.capture().pixels, cv::NORM_INF), 0.0);
}

TEST(CaptureSimCamera, SceneJsonErrorsNamePath) {
  try {
    parse_sim_scene(nlohmann::json::parse(R"({"object": {"radius_mm": -1}})"), "scene.json");
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("object.radius_mm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_sim_scene(nlohmann::json::parse(R"({"gian": 3})"), "s"), fest::Error);
}

}  // namespace

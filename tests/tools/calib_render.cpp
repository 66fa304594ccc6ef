// Synthetic calibration images with known geometry for capture's CLI tests and the
// example (scenes of tests/unit/calib_scenes.hpp, rendered by lib/capture/calib_synth):
//
//   calib_render camera DIR      DIR/cam.json (truth), DIR/c00.png ... c09.png
//   calib_render turntable DIR   DIR/cam.json, DIR/t00.png ... t11.png (0, 30, ... 330 degrees),
//                                DIR/truth.json {"axis", "t_T0"}
//   calib_render spheres DIR     DIR/cam.json, DIR/s0.png (three spheres), DIR/s1.png
//                                (the same spheres moved), DIR/truth.json {"light"}
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "calib_scenes.hpp"
#include "capture/calib_synth.hpp"
#include "core/file_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/table/table_io.hpp"

namespace {

using namespace fest;
using nlohmann::json;

json array(const cv::Matx33d& m) {
  json a = json::array();
  for (int i = 0; i < 9; ++i) a.push_back(m.val[i]);
  return a;
}
json array(const cv::Vec3d& v) { return json::array({v[0], v[1], v[2]}); }

void write_camera(const std::string& dir, const capture::Intrinsics& c) {
  json d = json::array();
  for (int i = 0; i < 5; ++i) d.push_back(c.dist[i]);
  write_output(dir + "/cam.json", formats::write_json({{"K", array(c.K)}, {"dist", d}, {"width", c.width}, {"height", c.height}}));
}

void write_png(const std::string& path, const cv::Mat& grey) {
  write_output(path, formats::write_image(Image{grey, ColorSpace::srgb}, formats::Format::png));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: calib_render camera|turntable|spheres DIR\n");
    return 2;
  }
  const std::string what = argv[1], dir = argv[2];
  try {
    if (what == "camera") {
      const capture::Intrinsics cam = test::camera(700, 640, 480, -0.15, 0.08);
      write_camera(dir, cam);
      const auto poses = test::calibration_poses();
      for (std::size_t i = 0; i < poses.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "/c%02zu.png", i);
        write_png(dir + name, capture::render_board(cam, capture::BoardSpec{9, 6, 25}, poses[i], 3));
      }
    } else if (what == "turntable") {
      const capture::Intrinsics cam = test::camera(900, 800, 600);
      const test::TurntableScene scene;
      write_camera(dir, cam);
      for (int k = 0; k < 12; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "/t%02d.png", k);
        write_png(dir + name, capture::render_board(cam, scene.board, scene.board_pose(30.0 * k), 3));
      }
      write_output(dir + "/truth.json", formats::write_json({{"axis", array(scene.axis())}, {"t_T0", array(scene.t_T0)}, {"R_T0", array(scene.R_T0)}}));
    } else if (what == "spheres") {
      const capture::Intrinsics cam = test::camera(1600, 1280, 960, -0.05, 0);
      test::SphereScene scene;
      write_camera(dir, cam);
      write_png(dir + "/s0.png", capture::render_spheres(cam, scene.spheres, scene.light, 2.0, 3));
      for (auto& s : scene.spheres) s.centre += cv::Vec3d(30, 40, -20);
      write_png(dir + "/s1.png", capture::render_spheres(cam, scene.spheres, scene.light, 2.0, 3));
      write_output(dir + "/truth.json", formats::write_json({{"light", array(scene.light)}}));
    } else {
      std::fprintf(stderr, "calib_render: unknown scene '%s'\n", what.c_str());
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "calib_render: %s\n", e.what());
    return 1;
  }
  return 0;
}

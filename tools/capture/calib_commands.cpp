#include "calib_commands.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/calib_board.hpp"
#include "capture/calib_camera.hpp"
#include "capture/calib_lights.hpp"
#include "capture/calib_turntable.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {
namespace {

using nlohmann::json;
using namespace fest::capture;

struct CameraArgs {
  std::string board;
  std::vector<std::string> images;
  bool fix_k3 = false, zero_tangent = false;
};

struct TurntableArgs {
  std::string camera, board, angles;
  std::vector<std::string> images;
};

struct LightsArgs {
  std::string camera, id = "L0";
  double ball_radius = 0;
  std::vector<std::string> images;
};

// The subcommands' flags live as long as the program (CLI11 binds to them).
struct State {
  CameraArgs camera;
  TurntableArgs turntable;
  LightsArgs lights;
  CLI::App* camera_cmd = nullptr;
  CLI::App* turntable_cmd = nullptr;
  CLI::App* lights_cmd = nullptr;
  bool quiet = false;
};

State& state() {
  static State s;
  return s;
}

void note(const std::string& message) {
  if (!state().quiet) warn("capture", message);
}

// One image as grey: float 0..1 and 8-bit (for the corner detector).
struct GreyImage {
  cv::Mat grey;
  cv::Mat grey8;
};

GreyImage read_grey(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::image)
    throw bad_input("{} data where an image was expected ({})", formats::kind_name(formats::kind_of(in.format)), path);
  const Image image = formats::parse(in, formats::read_image);
  return GreyImage{to_gray_float(image.pixels), to_gray8(image.pixels)};
}

void check_size(const cv::Mat& m, cv::Size& size, const std::string& first, const std::string& path) {
  if (size.area() == 0) {
    size = m.size();
    return;
  }
  if (m.size() != size)
    throw bad_input("image is {}x{}, {} is {}x{}: all views must come from one camera setting ({})", m.cols, m.rows,
                    first, size.width, size.height, path);
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

json array(const cv::Matx33d& m) {
  json a = json::array();
  for (int i = 0; i < 9; ++i) a.push_back(m.val[i]);
  return a;
}
template <int N>
json array(const cv::Vec<double, N>& v) {
  json a = json::array();
  for (int i = 0; i < N; ++i) a.push_back(v[i]);
  return a;
}

double number_at(const json& doc, const char* key, const std::string& path) {
  if (!doc.contains(key) || !doc[key].is_number()) throw bad_input("camera: '{}' missing or not a number ({})", key, path);
  return doc[key].get<double>();
}

// The camera.json that calib-camera writes (brdffit's cam.json fields).
Intrinsics read_camera(const std::string& path) {
  const json doc = formats::parse(formats::load_input(path), formats::read_json_document);
  if (!doc.is_object()) throw bad_input("camera: not a JSON object ({})", path);
  Intrinsics c;
  if (!doc.contains("K") || !doc["K"].is_array() || doc["K"].size() != 9)
    throw bad_input("camera: 'K' must hold 9 numbers ({})", path);
  for (int i = 0; i < 9; ++i) {
    if (!doc["K"][std::size_t(i)].is_number()) throw bad_input("camera: K[{}] is not a number ({})", i, path);
    c.K.val[i] = doc["K"][std::size_t(i)].get<double>();
  }
  if (doc.contains("dist")) {
    const json& d = doc["dist"];
    if (!d.is_array() || d.size() > 5) throw bad_input("camera: 'dist' must hold up to 5 numbers ({})", path);
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!d[i].is_number()) throw bad_input("camera: dist[{}] is not a number ({})", i, path);
      c.dist[int(i)] = d[i].get<double>();
    }
  }
  c.width = int(number_at(doc, "width", path));
  c.height = int(number_at(doc, "height", path));
  if (!(c.K(0, 0) > 0) || !(c.K(1, 1) > 0) || c.K(2, 2) != 1 || c.width <= 0 || c.height <= 0)
    throw bad_input("camera: K must have positive focal lengths and K[8] = 1, width and height positive ({})", path);
  return c;
}

void check_camera_size(const Intrinsics& cam, const cv::Mat& m, const std::string& camera_path, const std::string& path) {
  if (m.cols != cam.width || m.rows != cam.height)
    throw bad_input("image is {}x{} but the camera ({}) was calibrated at {}x{} ({})", m.cols, m.rows, camera_path,
                    cam.width, cam.height, path);
}

void emit(const json& doc) { write_output("-", formats::write_json(doc)); }

// Corners of every image that shows the whole board; images without one are named.
struct BoardViews {
  std::vector<std::string> used, missing;
  std::vector<std::vector<cv::Point2f>> corners;
  cv::Size size;
};

BoardViews find_boards(const std::vector<std::string>& images, const BoardSpec& board,
                       const std::function<void(const cv::Mat&, const std::string&)>& check = {}) {
  BoardViews v;
  for (const std::string& path : images) {
    const GreyImage g = read_grey(path);
    check_size(g.grey8, v.size, images.front(), path);
    if (check) check(g.grey8, path);
    auto corners = find_board_corners(g.grey8, board);
    if (corners.empty()) {
      v.missing.push_back(path);
      continue;
    }
    v.used.push_back(path);
    v.corners.push_back(std::move(corners));
  }
  if (v.used.empty())
    throw bad_input("no {}x{} board found in any image: {}", board.cols, board.rows, joined(v.missing));
  for (const std::string& m : v.missing) note(fmt::format("no {}x{} board found; image left out ({})", board.cols, board.rows, m));
  return v;
}

int run_camera(const CameraArgs& a) {
  const BoardSpec board = parse_board_spec(a.board);
  const BoardViews v = find_boards(a.images, board);
  CameraCalibOptions options;
  options.fix_k3 = a.fix_k3;
  options.zero_tangent = a.zero_tangent;
  const CameraCalibration cal = calibrate_camera(v.corners, board, v.size, options);
  const Intrinsics& k = cal.intrinsics;
  json views = json::array();
  for (std::size_t i = 0; i < v.used.size(); ++i) views.push_back({{"image", v.used[i]}, {"rms_px", cal.view_rms[i]}});
  json doc = {{"K", array(k.K)},
              {"dist", array(k.dist)},
              {"R", array(cv::Matx33d::eye())},
              {"t", json::array({0, 0, 0})},
              {"width", k.width},
              {"height", k.height},
              {"rms", cal.rms},
              {"board", a.board},
              {"views", views},
              {"left_out", v.missing}};
  emit(doc);
  return 0;
}

bool parse_double(const std::string& text, double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// --angles N (N equal steps over a revolution, in image order) or a list of degrees.
std::vector<double> parse_angles(const std::string& text, std::size_t images) {
  std::vector<double> angles;
  if (text.empty() || text.find(',') == std::string::npos) {
    double n = double(images);
    if (!text.empty() && (!parse_double(text, n) || n < 1 || n != std::floor(n)))
      throw usage_error("--angles: '{}' is neither a count nor a list of degrees (0,30,60,...)", text);
    for (int k = 0; k < int(n); ++k) angles.push_back(360.0 * k / n);
  } else {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      double d = 0;
      if (!parse_double(text.substr(start, comma - start), d))
        throw usage_error("--angles: '{}' is not a number of degrees", text.substr(start, comma - start));
      angles.push_back(d);
      start = comma + 1;
    }
  }
  if (angles.size() != images)
    throw bad_input("{} turntable angles for {} images: one angle per image, in order", angles.size(), images);
  return angles;
}

int run_turntable(const TurntableArgs& a) {
  const BoardSpec board = parse_board_spec(a.board);
  if (!board_has_orientation(board))
    throw usage_error("board {}x{}: a turntable needs inner corner counts of different parity (9x6, 7x4), so that "
                      "a half turn of the board can be told apart",
                      board.cols, board.rows);
  const Intrinsics cam = read_camera(a.camera);
  const std::vector<double> all_angles = parse_angles(a.angles, a.images.size());
  const BoardViews v = find_boards(a.images, board, [&](const cv::Mat& m, const std::string& path) {
    check_camera_size(cam, m, a.camera, path);
  });
  std::vector<double> angles;
  std::vector<Pose> poses;
  std::vector<double> reprojection;
  for (std::size_t i = 0, u = 0; i < a.images.size() && u < v.used.size(); ++i) {
    if (a.images[i] != v.used[u]) continue;
    angles.push_back(all_angles[i]);
    poses.push_back(board_pose(v.corners[u], board, cam));
    reprojection.push_back(reprojection_rms(v.corners[u], board, cam, poses.back()));
    ++u;
  }
  const TurntableCalibration cal = calibrate_turntable(poses, angles, board);
  json views = json::array();
  for (std::size_t k = 0; k < poses.size(); ++k)
    views.push_back({{"image", v.used[k]},
                     {"commanded_deg", angles[k]},
                     {"measured_deg", cal.measured_deg[k]},
                     {"residual_deg", cal.angle_residual_deg[k]},
                     {"circle_rms_mm", cal.circle_rms_mm[k]},
                     {"height_rms_mm", cal.height_rms_mm[k]},
                     {"reprojection_rms_px", reprojection[k]}});
  json doc = {{"R_T0", array(cal.R_T0)},
              {"t_T0", array(cal.t_T0)},
              {"axis", array(cal.axis)},
              {"axis_spread_deg", cal.axis_spread_deg},
              {"angle_rms_deg", cal.angle_rms_deg},
              {"board", a.board},
              {"camera", a.camera},
              {"views", views},
              {"left_out", v.missing}};
  emit(doc);
  return 0;
}

int run_lights(const LightsArgs& a) {
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
                         {"centre_mm", array(rays.back().centre)}});
    }
  }
  if (rays.empty()) throw bad_input("no chrome sphere with a highlight found in any image: {}", joined(missing));
  for (const std::string& m : missing) note(fmt::format("no sphere with a highlight found; image left out ({})", m));
  const LightFit fit = triangulate_light(rays);
  for (std::size_t i = 0; i < rays.size(); ++i) spheres[i]["ray_distance_mm"] = fit.ray_distance_mm[i];
  json doc = {{"lights", json::array({{{"id", a.id}, {"position", array(fit.position)}, {"residual_mm", fit.residual_rms_mm}, {"rays", rays.size()}}})},
              {"ball_radius_mm", a.ball_radius},
              {"camera", a.camera},
              {"spheres", spheres},
              {"images", used},
              {"left_out", missing}};
  emit(doc);
  return 0;
}

}  // namespace

void add_calib_commands(CLI::App& app) {
  State& s = state();
  s.camera_cmd = app.add_subcommand("calib-camera", "Camera intrinsics from chessboard images -> camera.json on stdout");
  s.camera_cmd->add_option("--board", s.camera.board, "Inner corners and square size: COLSxROWSxSIZE, e.g. 9x6x25mm")->required();
  s.camera_cmd->add_flag("--fix-k3", s.camera.fix_k3, "Keep k3 = 0 (few or mostly frontal views)");
  s.camera_cmd->add_flag("--zero-tangent", s.camera.zero_tangent, "Keep p1 = p2 = 0");
  s.camera_cmd->add_option("images", s.camera.images, "Images of the board in different poses (3 or more)")->required();

  s.turntable_cmd = app.add_subcommand(
      "calib-turntable", "Turntable axis and centre from a board lying on the table -> turntable_cal.json on stdout");
  s.turntable_cmd->add_option("--camera", s.turntable.camera, "Intrinsics (camera.json of calib-camera)")->required();
  s.turntable_cmd->add_option("--board", s.turntable.board, "Inner corners and square size, e.g. 9x6x25mm")->required();
  s.turntable_cmd->add_option("--angles", s.turntable.angles,
                              "Turntable angle of each image: N (N equal steps over 360 degrees) or a list 0,30,60,... "
                              "(default: one revolution in as many steps as images)");
  s.turntable_cmd->add_option("images", s.turntable.images, "One image per angle, in order")->required();

  s.lights_cmd = app.add_subcommand("calib-lights", "Light position from chrome spheres -> lights_cal.json on stdout");
  s.lights_cmd->add_option("--camera", s.lights.camera, "Intrinsics (camera.json of calib-camera)")->required();
  s.lights_cmd->add_option("--ball-radius", s.lights.ball_radius, "Sphere radius in mm")->required();
  s.lights_cmd->add_option("--id", s.lights.id, "Id of the light the images show");
  s.lights_cmd->add_option("images", s.lights.images, "Images of the spheres lit by this light alone")->required();
  // -q, -v and the other common flags of the app are accepted after the subcommand too.
  for (CLI::App* cmd : {s.camera_cmd, s.turntable_cmd, s.lights_cmd}) cmd->fallthrough();
}

int run_calib_command(const CLI::App& app) {
  State& s = state();
  try {
    s.quiet = app.get_option("--quiet")->as<bool>();
  } catch (const CLI::OptionNotFound&) {
    s.quiet = false;
  }
  if (s.camera_cmd && s.camera_cmd->parsed()) return run_camera(s.camera);
  if (s.turntable_cmd && s.turntable_cmd->parsed()) return run_turntable(s.turntable);
  if (s.lights_cmd && s.lights_cmd->parsed()) return run_lights(s.lights);
  return -1;
}

}  // namespace fest::capture_tool

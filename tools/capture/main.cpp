// capture: acquisition sessions on a turntable station (docs/capture.md).
// Flags only: they fill the typed options of commands.hpp (lists and notations parsed
// here), and the subcommand given runs through one call.

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "capture/calib_board.hpp"
#include "capture/plan.hpp"
#include "cli/cli.hpp"
#include "commands.hpp"

namespace {

using fest::usage_error;

// Light ids separated by commas: "L0,L1".
std::vector<std::string> ids(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t p = text.find(',', start);
    const std::string id = text.substr(start, p == std::string::npos ? std::string::npos : p - start);
    if (id.empty()) throw usage_error("empty light id in '{}'", text);
    out.push_back(id);
    if (p == std::string::npos) return out;
    start = p + 1;
  }
}

// A value in one of lib/capture's notations; its error names the flag.
template <typename T>
T notation(const char* flag, const std::function<T()>& parse) {
  try {
    return parse();
  } catch (const fest::Error& e) {
    throw fest::Error(e.status(), std::string(flag) + ": " + e.what());
  }
}

bool parse_double(const std::string& text, double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// calib-turntable --angles: N (N equal steps over a revolution, in image order) or a list
// of degrees.
void set_turntable_angles(fest::capture_tool::CalibTurntableOptions& o, const std::string& text) {
  o.angles_deg.clear();
  o.angle_count = 0;
  if (text.empty() || text.find(',') == std::string::npos) {
    double n = 0;
    if (!text.empty() && (!parse_double(text, n) || n < 1 || n != std::floor(n)))
      throw usage_error("--angles: '{}' is neither a count nor a list of degrees (0,30,60,...)", text);
    o.angle_count = int(n);
    return;
  }
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    double d = 0;
    if (!parse_double(text.substr(start, comma - start), d))
      throw usage_error("--angles: '{}' is not a number of degrees", text.substr(start, comma - start));
    o.angles_deg.push_back(d);
    start = comma + 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::capture_tool;
  namespace capture = fest::capture;
  CLI::App app{"Drive an appearance-capture station: plans, runs with a journaled manifest, selftest,\n"
               "calibration of its camera, turntable and lights",
               "capture"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  PlanOptions plan;
  CLI::App* p = app.add_subcommand("plan", "Write a plan.json from flags");
  p->add_option_function<std::string>(
      "--angles",
      [&plan](const std::string& text) {
        plan.angles_deg = notation<std::vector<double>>("--angles", [&] { return capture::angles_from_flag(text); });
      },
      "Turntable angles: a count (24 = every 15 deg) or a list 0,15,30");
  p->add_option_function<std::string>(
      "--lights",
      [&plan](const std::string& text) {
        plan.each_light = text == "each";
        plan.lights = plan.each_light ? std::vector<std::string>{} : ids(text);
      },
      "each (every light of role light) or a list L0,L1");
  p->add_option_function<std::string>(
      "--bracket",
      [&plan](const std::string& text) {
        plan.exposures_s = notation<std::vector<double>>("--bracket", [&] { return capture::exposures_from_flag(text); });
      },
      "Exposures BASE:STOPS:COUNT (1/1000:1:12) or a list 0.001,0.002");
  p->add_option_function<std::string>(
      "--silhouette",
      [&plan](const std::string& text) { plan.silhouette_lights = text.empty() ? std::vector<std::string>{} : ids(text); },
      "Backlight id(s) for one silhouette shot per view");
  p->add_option("--silhouette-exposure", plan.silhouette_exposure_s, "Exposure of the silhouette shot, s")
      ->check(fest::cli::positive);
  p->add_option("--lightcal", plan.lightcal, "Light-calibration (mirror ball) shots per view")->check(fest::cli::range(0, 100));
  p->add_option("--dark", plan.dark, "Dark frames (all lights off) per view")->check(fest::cli::range(0, 100));
  p->add_option("--repeat", plan.repeat, "Takes of every exposure (hdrmerge averages them: less noise)")
      ->check(fest::cli::range(1, 100));

  RunOptions run;
  CLI::App* r = app.add_subcommand("run", "Run a plan on the station; the manifest on standard output");
  r->add_option("--station", run.station, "station.json")->envname("CAPTURE_STATION");
  r->add_option("--plan", run.plan, "plan.json")->required();
  r->add_option("-o,--output", run.session, "Session folder");
  r->add_flag("--resume", run.resume, "Continue an interrupted session, keeping shots whose files hash as recorded");
  r->add_flag("--dry-run", run.dry_run, "Print the plan, its shots and a time estimate; touch no device");
  r->add_flag("--allow-jpeg", run.allow_jpeg, "Accept a station asking for JPEG (lossy: refused by default)");
  fest::cli::add_progress(*r, run.progress);

  SelftestOptions self;
  CLI::App* s = app.add_subcommand("selftest", "Check every device of the station; a JSON report");
  s->add_option("--station", self.station, "station.json")->envname("CAPTURE_STATION");

  // The calibration subcommands (docs/capture.md §5).
  CalibCameraOptions cam;
  CLI::App* cc = app.add_subcommand("calib-camera", "Camera intrinsics from chessboard images -> camera.json on stdout");
  cc->add_option_function<std::string>(
        "--board",
        [&cam](const std::string& text) {
          cam.board = capture::parse_board_spec(text);
          cam.board_name = text;
        },
        "Inner corners and square size: COLSxROWSxSIZE, e.g. 9x6x25mm")
      ->required();
  cc->add_flag("--fix-k3", cam.fix_k3, "Keep k3 = 0 (few or mostly frontal views)");
  cc->add_flag("--zero-tangent", cam.zero_tangent, "Keep p1 = p2 = 0");
  cc->add_option("images", cam.images, "Images of the board in different poses (3 or more)")->required();

  CalibTurntableOptions table;
  CLI::App* ct = app.add_subcommand(
      "calib-turntable", "Turntable axis and centre from a board lying on the table -> turntable_cal.json on stdout");
  ct->add_option("--camera", table.camera, "Intrinsics (camera.json of calib-camera)")->required();
  ct->add_option_function<std::string>(
        "--board",
        [&table](const std::string& text) {
          table.board = capture::parse_board_spec(text);
          table.board_name = text;
        },
        "Inner corners and square size, e.g. 9x6x25mm")
      ->required();
  ct->add_option_function<std::string>(
      "--angles", [&table](const std::string& text) { set_turntable_angles(table, text); },
      "Turntable angle of each image: N (N equal steps over 360 degrees) or a list 0,30,60,... "
      "(default: one revolution in as many steps as images)");
  ct->add_option("images", table.images, "One image per angle, in order")->required();

  CalibLightsOptions lights;
  CLI::App* cl = app.add_subcommand("calib-lights", "Light position from chrome spheres -> lights_cal.json on stdout");
  cl->add_option("--camera", lights.camera, "Intrinsics (camera.json of calib-camera)")->required();
  cl->add_option("--ball-radius", lights.ball_radius, "Sphere radius in mm")->required();
  cl->add_option("--id", lights.id, "Id of the light the images show");
  cl->add_option("images", lights.images, "Images of the spheres lit by this light alone")->required();
  // -q, -v and the other common flags of the app are accepted after the subcommand too.
  for (CLI::App* cmd : {cc, ct, cl}) cmd->fallthrough();

  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error,\n"
             "5 device not found, 6 device error, 7 timeout, 8 permission denied. See capture(1).");
  // The outer frame reports errors thrown from CLI11 callbacks during parsing too.
  return fest::run_tool("capture", [&] {
    return fest::cli::run(app, argc, argv, [&] {
      cam.quiet = table.quiet = lights.quiet = common.quiet;
      if (p->parsed()) return plan_command(plan);
      if (r->parsed()) return run_command(run);
      if (s->parsed()) return selftest_command(self);
      if (cc->parsed()) return calib_camera_command(cam);
      if (ct->parsed()) return calib_turntable_command(table);
      return calib_lights_command(lights);
    });
  });
}

// quatpath: key poses (position + orientation quaternion) in, per-frame poses out --
// spline positions, slerp/squad orientations with per-segment reversal, constant speed
// by arc length, resampling to a frame rate (seed 004 §18, docs/quatpath.md).
//
// Wiring only: this file maps flags onto commands.hpp.

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

using namespace fest::quatpath_tool;

int main(int argc, char** argv) {
  CLI::App app{"Key-framed motion paths: spline positions, quaternion slerp/squad orientations (short or long\n"
               "way per segment), constant speed by arc length, poses at a frame rate.",
               "quatpath"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  PathArgs a;
  app.add_option("input", a.input, "Keys: CSV/TSV t,x,y,z,qw,qx,qy,qz[,way][,tension,continuity,bias] or JSON Lines; - = standard input");
  app.add_option("-o,--output", a.output, "Poses (.csv, .jsonl) or cameras; - = standard output");
  PoseFormat to = PoseFormat::csv;
  CLI::Option* to_flag = fest::cli::enum_words<PoseFormat>(
      app.add_option("--to", to, "Output: csv, jsonl, camera (terrainlod --path JSON Lines), or camera-args (volrender look-at flags, one line per frame)"),
      {{"csv", PoseFormat::csv}, {"jsonl", PoseFormat::jsonl}, {"camera", PoseFormat::camera}, {"camera-args", PoseFormat::camera_args}});
  app.add_option("--fps", a.fps, "Output frames per second")->check(fest::cli::positive);
  using fest::motionpath::OrientationMode;
  using fest::motionpath::PositionMode;
  using fest::motionpath::Way;
  fest::cli::enum_words<OrientationMode>(app.add_option("--orientation", a.orientation, "slerp (piecewise great arcs) or squad (C1 at the keys)"),
                                         {{"slerp", OrientationMode::slerp}, {"squad", OrientationMode::squad}});
  fest::cli::enum_words<PositionMode>(
      app.add_option("--position", a.position, "linear, catmull-rom, or kb (Kochanek-Bartels; tension/continuity/bias columns)"),
      {{"linear", PositionMode::linear}, {"catmull-rom", PositionMode::catmull_rom}, {"kb", PositionMode::kb}});
  fest::cli::enum_words<Way>(app.add_option("--way", a.way, "Default turn of a segment: short, or long (the other way round); a key's way column wins"),
                             {{"short", Way::shortest}, {"long", Way::longest}});
  app.add_flag("--constant-speed", a.constant_speed, "Reparametrise by arc length: constant speed from the first key's time to the last");
  app.add_flag("--no-end", a.no_end, "Do not add a last frame at the last key's time when it falls between frames");
  app.add_option("--camera-distance", a.camera_distance, "Camera output: target = eye + distance x view direction")
      ->check(fest::cli::positive);
  app.add_option("--fovy", a.fovy_deg, "Camera output: vertical field of view in degrees")->check(fest::cli::range(1.0, 179.0));
  app.add_option("--width", a.width, "Camera output: image width")->check(fest::cli::range(1, 65536));
  app.add_option("--height", a.height, "Camera output: image height")->check(fest::cli::range(1, 65536));
  app.add_option("--tau", a.tau_px, "Camera output: terrainlod's screen-space error tau_px")->check(fest::cli::positive);
  app.add_option("--report", a.report, "JSON report: keys, frames, length, unit-norm error, frame step range");
  return fest::cli::run(app, argc, argv, [&] {
    if (to_flag->count() > 0) a.to = to;
    a.quiet = common.quiet;
    return cmd_path(a);
  });
}

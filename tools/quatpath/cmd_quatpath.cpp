// quatpath: read keys, build the path, sample it at --fps, write poses or cameras.

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/tool_main.hpp"
#include "keys_io.hpp"
#include "motionpath/path.hpp"

namespace fest::quatpath_tool {

namespace {
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

int cmd_path(const PathArgs& a) {
  PoseFormat to = PoseFormat::csv;
  if (a.to) to = *a.to;
  else if (ends_with(a.output, ".jsonl") || ends_with(a.output, ".json")) to = PoseFormat::jsonl;
  const std::string name = input_name(a.input);
  int dropped = 0;
  const motionpath::Way default_way = a.way;
  std::vector<motionpath::Key> keys;
  keys = read_keys(read_input(a.input), name, default_way, dropped);
  if (dropped > 0) throw bad_input("the key table has {} column(s) quatpath does not use (known: t,x,y,z,qw,qx,qy,qz,way,tension,continuity,bias) ({})", dropped, name);
  double worst_input_norm = 0;
  for (const auto& k : keys) worst_input_norm = std::max(worst_input_norm, std::fabs(motionpath::norm(k.q) - 1.0));

  motionpath::PathOptions opt;
  opt.orientation = a.orientation;
  opt.position = a.position;
  opt.constant_speed = a.constant_speed;
  try {
    const motionpath::Path path(keys, opt);
    if (worst_input_norm > 1e-6 && !a.quiet)
      warn("quatpath", fmt::format("key quaternions were not unit (largest | |q| - 1 | = {:.3g}); normalised", worst_input_norm));
    const auto poses = path.sample(a.fps, !a.no_end);
    std::string bytes;
    if (to == PoseFormat::csv) bytes = write_csv(poses);
    else if (to == PoseFormat::jsonl) bytes = write_jsonl(poses);
    else if (to == PoseFormat::camera_args) bytes = write_camera_args(poses, CameraOptions{a.camera_distance, a.fovy_deg, a.width, a.height, a.tau_px});
    else bytes = write_cameras(poses, CameraOptions{a.camera_distance, a.fovy_deg, a.width, a.height, a.tau_px});
    write_output(a.output, bytes);
    if (!a.report.empty()) {
      double worst_unit = 0, lo = 1e300, hi = 0;
      for (std::size_t i = 0; i < poses.size(); ++i) {
        worst_unit = std::max(worst_unit, std::fabs(motionpath::norm(poses[i].q) - 1.0));
        if (i > 0) {
          const double d = motionpath::norm(poses[i].p - poses[i - 1].p);
          lo = std::min(lo, d);
          hi = std::max(hi, d);
        }
      }
      nlohmann::json r = {{"keys", keys.size()},
                          {"frames", poses.size()},
                          {"fps", a.fps},
                          {"length", path.length()},
                          {"duration", path.t_end() - path.t_begin()},
                          {"max_unit_error", worst_unit},
                          {"min_frame_step", poses.size() > 1 ? lo : 0.0},
                          {"max_frame_step", poses.size() > 1 ? hi : 0.0}};
      write_output(a.report, r.dump(2) + "\n");
    }
  } catch (const Error& e) {
    if (e.status() == Status::bad_input) throw Error(e.status(), fmt::format("{} ({})", e.what(), name));
    throw;
  }
  return 0;
}

}  // namespace fest::quatpath_tool

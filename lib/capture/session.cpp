#include "capture/session.hpp"

#include <cmath>
#include <set>

namespace fest::capture {
namespace {

void set_lights(LightBank& lights, const std::vector<std::string>& on) {
  const std::set<std::string> wanted(on.begin(), on.end());
  for (const LightState& l : lights.list())
    if (l.on && !wanted.count(l.id)) lights.set(l.id, false);
  for (const std::string& id : on) lights.set(id, true);
}

}  // namespace

SessionOutcome run_session(Turntable& table, LightBank& lights, Camera& camera, const std::vector<PlannedShot>& shots,
                           const SessionOptions& options, ShotSink& sink) {
  SessionOutcome outcome;
  std::string step = "switch all lights off";
  try {
    lights.all_off();
    std::size_t i = 0;
    while (i < shots.size()) {
      // The shots of one view: consecutive entries with the same angle index.
      std::size_t end = i;
      while (end < shots.size() && shots[end].angle_index == shots[i].angle_index) ++end;
      std::vector<const PlannedShot*> todo;
      for (std::size_t j = i; j < end; ++j) {
        if (sink.done(shots[j])) ++outcome.shots_skipped;
        else todo.push_back(&shots[j]);
      }
      const auto report = [&] {
        if (options.progress) options.progress(outcome.shots_taken + outcome.shots_skipped, shots.size());
      };
      report();
      if (!todo.empty()) {
        const PlannedShot& first = shots[i];
        step = fmt::format("move to angle {} ({} deg)", first.angle_index, first.angle_cmd_deg);
        const MoveResult move = move_to_angle(table, first.angle_cmd_deg, options.motion);
        table.wait_ms(options.settle_ms);
        const ShotPose pose{move.angle_deg, move.steps};
        std::vector<std::string> lit;
        double exposure = -1;
        for (const PlannedShot* s : todo) {
          if (options.cancel && options.cancel->load()) {
            step = fmt::format("before {}", s->file);
            throw runtime_failure("interrupted by a signal");
          }
          if (s->lights_on != lit) {
            step = fmt::format("switch lights for {}", s->file);
            set_lights(lights, s->lights_on);
            lit = s->lights_on;
            unsigned warm = 0;
            if (options.warmup_ms)
              for (const std::string& id : lit) warm = std::max(warm, options.warmup_ms(id));
            if (warm) table.wait_ms(warm);
          }
          step = fmt::format("capture {}", s->file);
          if (s->exposure_s != exposure) {
            camera.set_exposure(s->exposure_s);
            exposure = s->exposure_s;
            for (int k = 0; k < options.flush_frames; ++k) camera.capture();
          }
          camera.set_repeat_index(s->repeat_index);
          const Image image = camera.capture();
          step = fmt::format("store {}", s->file);
          sink.store(*s, pose, image);
          ++outcome.shots_taken;
          report();
        }
        step = fmt::format("switch all lights off after angle {}", first.angle_index);
        lights.all_off();
      }
      i = end;
    }
    step = "store the last shots";
    sink.finish();
    outcome.complete = true;
    return outcome;
  } catch (const Error& e) {
    outcome.status = e.status();
    outcome.message = e.what();
  } catch (const std::exception& e) {
    outcome.status = Status::failure;
    outcome.message = e.what();
  }
  outcome.failed_step = step;
  // Safe state first: lights off, table stopped. A device that is gone throws again.
  try {
    lights.all_off();
  } catch (const std::exception&) {
  }
  try {
    table.stop(true);
  } catch (const std::exception&) {
  }
  return outcome;
}

double estimate_session_s(const std::vector<PlannedShot>& shots, const SessionOptions& options, double deg_per_s,
                          double per_shot_s) {
  double total = 0, at = 0;
  int angle = -1;
  std::vector<std::string> lit;
  double exposure = -1;
  for (const PlannedShot& s : shots) {
    if (s.angle_index != angle) {
      const double distance = std::fabs(s.angle_cmd_deg - at) + (s.angle_cmd_deg < at ? 2 * options.motion.backlash_deg : 0);
      total += distance / deg_per_s + options.settle_ms / 1000.0;
      at = s.angle_cmd_deg;
      angle = s.angle_index;
      lit.clear();
    }
    if (s.lights_on != lit && options.warmup_ms) {
      unsigned warm = 0;
      for (const std::string& id : s.lights_on) warm = std::max(warm, options.warmup_ms(id));
      total += warm / 1000.0;
      lit = s.lights_on;
    }
    const int frames = 1 + (s.exposure_s != exposure ? options.flush_frames : 0);
    exposure = s.exposure_s;
    total += frames * (s.exposure_s + per_shot_s);
  }
  return total;
}

}  // namespace fest::capture

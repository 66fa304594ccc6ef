#pragma once
// The acquisition loop of docs/capture.md §2, free of I/O: devices in, pictures out
// through a ShotSink (the tool writes files and the journal). Mechanics outermost,
// exposures innermost; on any error every light goes off and the table stops before the
// outcome names the failing step.

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "capture/camera.hpp"
#include "capture/light_bank.hpp"
#include "capture/plan.hpp"
#include "capture/turntable.hpp"
#include "core/error.hpp"
#include "core/progress_callback.hpp"

namespace fest::capture {

// Where a shot was taken, as the manifest records it.
struct ShotPose {
  double angle_deg = 0;  // executed: steps * 360 / S_rev
  std::int32_t angle_steps = 0;
};

class ShotSink {
 public:
  virtual ~ShotSink() = default;
  // True when the shot is already stored intact (resume): the loop skips it.
  virtual bool done(const PlannedShot& shot) = 0;
  virtual void store(const PlannedShot& shot, const ShotPose& pose, const Image& image) = 0;
  // Called once after the last shot: a sink that stores in the background finishes here
  // and reports its errors.
  virtual void finish() {}
};

struct SessionOptions {
  MotionPolicy motion;
  unsigned settle_ms = 500;
  int flush_frames = 0;
  std::function<unsigned(const std::string& light)> warmup_ms;  // may be empty
  const std::atomic<bool>* cancel = nullptr;  // set by a signal handler: stop between shots
  ProgressFn progress;  // shots taken or kept from before (--resume) of all the plan's shots
};

struct SessionOutcome {
  bool complete = false;
  Status status = Status::ok;  // of the error that stopped it
  std::string failed_step;     // "move to angle 3 (45 deg)", "capture a003/L0/e05.png", ...
  std::string message;
  int shots_taken = 0, shots_skipped = 0;
};

// Runs the shots (expand_plan order; consecutive shots at one angle index share a move).
// Errors of the devices and of the sink end the session with an outcome, not an exception;
// the lights are switched off and the table stopped (errors while doing that are ignored:
// a device that is gone cannot be switched). Waits (settle, warm-up) go through
// table.wait_ms, which a simulator runs in virtual time.
SessionOutcome run_session(Turntable& table, LightBank& lights, Camera& camera, const std::vector<PlannedShot>& shots,
                           const SessionOptions& options, ShotSink& sink);

// Seconds the plan will take: exposures, flush frames, settle and warm-up times, moves at
// `deg_per_s`, and `per_shot_s` of overhead per picture.
double estimate_session_s(const std::vector<PlannedShot>& shots, const SessionOptions& options, double deg_per_s,
                          double per_shot_s);

}  // namespace fest::capture

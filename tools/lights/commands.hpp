#pragma once
// lights' subcommands (docs/lights.md), each taking its typed options. main.cpp fills
// these from flags; everything else in this folder is the fest_lights_app library.

#include <string>
#include <vector>

namespace fest::lights_tool {

// The station whose "lights" array names the lights (empty: $CAPTURE_STATION).
struct StationOptions {
  std::string station;
};

struct OffOptions {
  std::vector<std::string> ids;
  bool all = false;  // every light of the station (instead of ids)
};

struct PulseOptions {
  std::string id;
  long ms = 1;  // on for this many milliseconds
};

struct HoldOptions {
  std::vector<std::string> ids;
  double seconds = 0;  // > 0: this long; else until SIGINT/SIGTERM/SIGHUP
};

// Blocks SIGINT/SIGTERM/SIGHUP for the whole process, so that they are only ever received
// by the wait of pulse and hold (docs/lights.md §2): no signal can end the process
// between switching a light on and switching it off again. Call it first in main.
void block_stop_signals();

int list_command(const StationOptions& s);
int on_command(const StationOptions& s, const std::vector<std::string>& ids);
int off_command(const StationOptions& s, const OffOptions& o);
int only_command(const StationOptions& s, const std::string& id);
int pulse_command(const StationOptions& s, const PulseOptions& o);
int hold_command(const StationOptions& s, const HoldOptions& o);

}  // namespace fest::lights_tool

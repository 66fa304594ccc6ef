#pragma once
// patnet's subcommands (docs/patnet.md "Command line"), each taking its parsed options.

#include <cstdint>
#include <string>
#include <vector>

#include "trace_writer.hpp"

namespace fest::patnet_tool {

struct RunArgs {
  std::vector<std::string> files;
  std::int64_t cycles = -1;
  double until = -1;
  double dt = 1.0 / 30.0;
  double t0 = 0.0;
  std::uint64_t seed = 1;
  std::string events;
  std::string table;
  std::string table_var;
  TraceFormat trace = TraceFormat::json;  // json, tsv or none; --raw-print makes it raw
  bool raw_print = false;
  bool dump_locals = false;
  std::vector<std::string> evals;
  std::int64_t max_cycles = 1000000;
  std::int64_t max_nets = 100000;
  std::int64_t max_steps = 1000000;
  bool strict = false;
  bool realtime = false;
  bool verbose = false;
  std::string report;
};

struct CheckArgs {
  std::vector<std::string> files;
  bool quiet = false;
};

struct DotArgs {
  std::vector<std::string> files;
  std::string class_name;
  std::string output = "-";
};

struct MarkovArgs {
  std::string input = "-";
  std::vector<std::string> cols{"turn_state", "gaze1", "gaze2"};  // three (turn state, gaze1, gaze2) or one state column
  int states = 24;
  bool no_self = false;
  std::string net;
  std::string output = "-";
  bool quiet = false;
};

int cmd_run(const RunArgs& a);
int cmd_check(const CheckArgs& a);
int cmd_dot(const DotArgs& a);
int cmd_markov(const MarkovArgs& a);

}  // namespace fest::patnet_tool

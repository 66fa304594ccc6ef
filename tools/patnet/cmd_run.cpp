// patnet run: load the files, apply --eval, run the scheduler, stream the trace.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/stopwatch.hpp"
#include "core/tool_main.hpp"
#include "inputs.hpp"
#include "patnet/machine.hpp"
#include "trace_writer.hpp"

namespace fest::patnet_tool {

namespace {

// Static checks of every file before anything runs, so that a bad net leaves standard
// output empty (exit 3 with the first error's position).
void check_first(const std::vector<std::pair<std::string, std::string>>& sources, bool verbose) {
  patnet::Machine probe;
  for (const auto& [name, text] : sources) probe.load(text, name, false);
  probe.finish_checks();
  for (const auto& d : probe.diagnostics())
    if (d.error) throw bad_input("{}", d.text());
  if (verbose)
    for (const auto& d : probe.diagnostics()) warn("patnet", d.text());
}

}  // namespace

int cmd_run(const RunArgs& a) {
  const Stopwatch clock;
  std::vector<std::pair<std::string, std::string>> sources;
  for (const std::string& f : a.files) sources.emplace_back(f, read_input(f));
  check_first(sources, a.verbose);

  patnet::RunOptions opt;
  opt.dt = a.dt;
  opt.t0 = a.t0;
  opt.seed = a.seed;
  opt.cycles = a.cycles;
  if (a.until >= 0) opt.until = a.until;
  opt.max_cycles = a.max_cycles;
  opt.max_nets = a.max_nets;
  opt.max_steps = a.max_steps;
  opt.strict = a.strict;
  opt.dump_locals = a.dump_locals;
  const TraceFormat format = a.raw_print ? TraceFormat::raw : a.trace;
  TraceWriter writer(stdout, format);
  writer.hold(true);
  patnet::Machine m(opt, &writer);
  try {
    for (const auto& [name, text] : sources) m.load(text, name, true);
    for (std::size_t i = 0; i < a.evals.size(); ++i) {
      try {
        m.eval_text(a.evals[i], fmt::format("--eval #{}", i + 1));
      } catch (const patnet::LispError& e) {
        throw bad_input("{} (--eval #{}: {})", e.message, i + 1, a.evals[i]);
      }
    }
    if (!a.events.empty()) m.set_inputs(parse_events(read_input(a.events), input_name(a.events), m));
    if (!a.table.empty()) m.set_table(parse_table(read_input(a.table), a.table, a.table_var));
  } catch (const patnet::LimitError& e) {
    throw runtime_failure("{} (while loading)", e.message);
  }
  writer.hold(false);
  if (a.realtime) {
    // Interactive use: cycle k starts when k dt seconds have passed, and the trace so far
    // is on standard output by then.
    const auto wall0 = std::chrono::steady_clock::now();
    const double t_first = opt.t0;
    m.set_cycle_hook([&writer, wall0, t_first](std::int64_t, double t) {
      writer.flush();
      std::fflush(stdout);
      std::this_thread::sleep_until(wall0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                std::chrono::duration<double>(t - t_first)));
    });
  }
  patnet::RunSummary sum;
  try {
    sum = m.run();
  } catch (...) {
    writer.flush();  // the trace so far, ending with the error event
    std::fflush(stdout);
    throw;
  }
  writer.flush();
  if (std::fflush(stdout) != 0) throw io_error("cannot write the trace to standard output");
  const double seconds = clock.seconds();
  if (!a.report.empty()) {
    nlohmann::json r = {{"cycles", sum.cycles},     {"instances", sum.instances}, {"finished", sum.finished},
                        {"failed", sum.failed},     {"errors", sum.errors},       {"deadlock", sum.deadlock},
                        {"events", writer.events()}, {"seconds", seconds},        {"seed", a.seed}};
    write_output(a.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::patnet_tool

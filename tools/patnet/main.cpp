// patnet: Parallel Transition Networks (PaT-Nets) -- load nets written in PaT-Lisp, run
// any number of instances time-sliced in fixed cycles, trace what they do; check, draw
// and estimate nets (docs/patnet.md).
//
// Wiring only: this file maps flags onto commands.hpp.

#include <sstream>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

using namespace fest::patnet_tool;

int main(int argc, char** argv) {
  CLI::App app{"PaT-Nets: parallel transition networks (nodes with actions, arcs with conditions, monitors,\n"
               "waits, semaphores, probabilistic nodes, inheritance) run in fixed cycles with a deterministic trace.",
               "patnet"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  RunArgs run;
  auto* r = app.add_subcommand("run", "Load the net files in order, run every instance, trace on standard output");
  r->add_option("files", run.files, "PaT-Lisp files (.pat), loaded in order; - = standard input")->required();
  auto* cyc = r->add_option("--cycles", run.cycles, "Stop after N cycles")->check(fest::cli::non_negative);
  r->add_option("--until", run.until, "Stop once the motion time reaches T seconds")->check(fest::cli::non_negative)->excludes(cyc);
  r->add_option("--dt", run.dt, "Seconds per cycle (default 1/30, Jack's 30 fps)")->check(fest::cli::positive);
  r->add_option("--t0", run.t0, "Motion time at cycle 0");
  r->add_option("--seed", run.seed, "Seed of the random stream (probabilistic nodes, RANDOM)");
  r->add_option("--events", run.events, "JSON Lines input events (set, motion, motion-done, spawn, eval); - = standard input");
  auto* tab = r->add_option("--table", run.table, "TSV with a t column; the current row is bound to --table-var");
  r->add_option("--table-var", run.table_var, "Global variable that holds the table row as an association list")->needs(tab);
  fest::cli::enum_words<TraceFormat>(r->add_option("--trace", run.trace, "Trace format: json (JSON Lines), tsv, or none"),
                                     {{"json", TraceFormat::json}, {"tsv", TraceFormat::tsv}, {"none", TraceFormat::none}});
  r->add_flag("--raw-print", run.raw_print, "Write only the text of (format t ...) to standard output");
  r->add_flag("--dump-locals", run.dump_locals, "Add each instance's locals to its exit event");
  r->add_option("--eval", run.evals, "An expression to evaluate after loading (repeatable)")->allow_extra_args(false);
  r->add_option("--max-cycles", run.max_cycles, "Fail (exit 1) when the run needs more cycles")->check(fest::cli::positive);
  r->add_option("--max-nets", run.max_nets, "Fail (exit 1) when more instances are created")->check(fest::cli::positive);
  r->add_option("--max-steps", run.max_steps, "Fail (exit 1) when one action, condition or monitor evaluates more steps")
      ->check(fest::cli::positive);
  r->add_flag("--realtime", run.realtime, "Pace cycles with the wall clock (motion time = seconds since the start)");
  r->add_flag("--strict", run.strict, "Run-time errors and deadlock end the run with exit 1");
  r->add_option("--report", run.report, "JSON report: cycles, instances, statuses, events, seconds");

  CheckArgs check;
  auto* c = app.add_subcommand("check", "Static checks: report problems with file:line:col; exit 3 on errors");
  c->add_option("files", check.files, "PaT-Lisp files")->required();

  DotArgs dot;
  auto* d = app.add_subcommand("dot", "Graphviz drawing of the net classes");
  d->add_option("files", dot.files, "PaT-Lisp files")->required();
  d->add_option("--class", dot.class_name, "Only this class");
  d->add_option("-o,--output", dot.output, "Output .dot file; - = standard output");

  MarkovArgs markov;
  auto* m = app.add_subcommand("markov", "Transition probabilities of a transcript's states, as a matrix or a net");
  m->add_option("input", markov.input, "Transcript (TSV or CSV with a header); - = standard input");
  std::string markov_cols = "turn_state,gaze1,gaze2";
  m->add_option("--cols", markov_cols, "turn-state,gaze1,gaze2 columns (24 states), or one state column");
  m->add_option("--states", markov.states, "Number of states with one state column")->check(fest::cli::range(1, 100000));
  m->add_flag("--no-self", markov.no_self, "Count only changes of state (no i -> i transitions)");
  m->add_option("--net", markov.net, "Write a .pat net of def-probnodes with this class name instead of the CSV matrix");
  m->add_option("-o,--output", markov.output, "Output file; - = standard output");

  return fest::cli::run(app, argc, argv, [&] {
    if (*r) {
      run.verbose = common.verbose;
      return cmd_run(run);
    }
    if (*c) {
      check.quiet = common.quiet;
      return cmd_check(check);
    }
    if (*d) return cmd_dot(dot);
    std::stringstream cols(markov_cols);  // names may be empty: the transcript then lacks that column
    markov.cols.clear();
    for (std::string col; std::getline(cols, col, ',');) markov.cols.push_back(col);
    if (markov.cols.size() != 3 && markov.cols.size() != 1)
      throw fest::usage_error("--cols takes three columns (turn state, gaze1, gaze2) or one state column");
    markov.quiet = common.quiet;
    return cmd_markov(markov);
  });
}

// segbrain: knowledge-based extraction of head and brain from MRI head volumes
// (Ehricke, seed 000 chapter 2; docs/segbrain.md). This file only declares the flags
// and turns them into the typed options of commands.hpp.

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/implied_subcommand.hpp"
#include "commands.hpp"

using namespace fest::segbrain_tool;

namespace {

// The flags of `run` as they are typed, before main turns them into RunArgs.
struct RunFlagText {
  std::string to, objects;
  std::vector<std::string> sets;
};

// Adds the flags of `run` to `cmd`; returns them so that main can tell whether any was given.
std::vector<CLI::Option*> add_run_flags(CLI::App& cmd, RunArgs& run, RunFlagText& text) {
  std::vector<CLI::Option*> o;
  o.push_back(cmd.add_option("input", run.input, "Input volume (NIfTI .nii/.nii.gz, NRRD, MHA; - = stdin)")->default_val("-"));
  o.push_back(cmd.add_option("-i", run.input, "Alias of the input argument"));
  o.push_back(cmd.add_option("-o,--output", run.output, "Label volume output (- = stdout)")->default_val("-"));
  o.push_back(cmd.add_option("--to", text.to, "Output format: nii | nii.gz | nrrd | mha (default from -o, else nii)"));
  o.push_back(cmd.add_option("--kb", run.kb, "Knowledge-base file(s) instead of the built-in head_t1.pl")->allow_extra_args(false));
  o.push_back(cmd.add_option("--goal", run.goal, "Goal to prove")->default_val("segment_head"));
  o.push_back(cmd.add_option("--set", text.sets, "NAME=VALUE: replace candidates/2, limit/2 or NAME/1 facts")->allow_extra_args(false));
  o.push_back(cmd.add_option("--objects", text.objects, "Comma-separated objects to find (head, brain, ventricles, cerebellum, brainstem, eyes, optic_nerve); "
                             "proves segment_objects([...]) instead of --goal"));
  o.push_back(cmd.add_option("--masks", run.masks, "Also write each emitted object as DIR/<name>.nii.gz (uint8 0/1)"));
  o.push_back(cmd.add_option("--label-table", run.label_table, "Write the label colour table (index name R G B A) of the knowledge base"));
  o.push_back(cmd.add_option("--report", run.report, "Write a JSON report"));
  o.push_back(cmd.add_option("--trace", run.trace, "Write the proof trace as JSON lines"));
  o.push_back(fest::cli::enum_words<Modality>(cmd.add_option("--modality", run.modality, "Contrast of the input: t1 | t2 | pd (the knowledge base must support it; "
                                                   "the built-in one supports t1)"),
                                    {{"t1", Modality::t1}, {"t2", Modality::t2}, {"pd", Modality::pd}})
                  ->default_str("t1"));
  o.push_back(cmd.add_flag("--tissue", run.tissue, "Also label grey (4) and white matter (5) inside the brain"));
  o.push_back(cmd.add_option("--max-depth", run.max_depth, "Deepest proof")->default_val(10000)->check(fest::cli::range(1, 100000000)));
  o.push_back(cmd.add_option("--max-inferences", run.max_inferences, "Most inferences")->default_val(1e7));
  o.push_back(cmd.add_option("--time-limit", run.time_limit, "Seconds (0 = none)")->default_val(0));
  fest::cli::add_threads(cmd, run.threads);
  o.push_back(cmd.get_option("--threads"));
  fest::cli::add_progress(cmd, run.progress);
  o.push_back(cmd.get_option("--progress"));
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Rule-based extraction of head and brain from T1 MRI head volumes: a Prolog-subset\n"
               "knowledge base drives operators, verification and retries; every decision is traced.",
               "segbrain"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.footer("Exit status: 0 success, 1 goal failed or limit hit, 2 usage error, 3 bad input or KB error,\n"
             "4 I/O error. See segbrain(1).");

  // `segbrain IN ...` means `segbrain run IN ...` (segbrain(1)): the main command takes
  // run's flags too, and runs when no subcommand is named.
  RunArgs run;
  RunFlagText run_text;
  fest::cli::imply_subcommand(app, add_run_flags(app, run, run_text), "Options of run (also without the word run)", {}, true);
  auto* r = app.add_subcommand("run", "Segment a volume (the default subcommand); the label volume to standard output or -o");
  r->fallthrough();  // -q/-v of the main command also after "run"
  add_run_flags(*r, run, run_text);

  KbCheckArgs kbc;
  auto* k = app.add_subcommand("kb-check", "Lint knowledge-base files: syntax, undefined predicates, singletons");
  k->add_option("files", kbc.files, "Rule files (none = the built-in head_t1.pl)")->allow_extra_args(false);

  OpsArgs ops;
  auto* o = app.add_subcommand("ops", "List the operator predicates and their modes");
  o->add_flag("--json", ops.json, "As JSON");

  SynthArgs syn;
  std::string syn_size, syn_spacing;
  auto* s = app.add_subcommand("synth", "Write the synthetic T1 head phantom and its truth labels");
  s->add_option("-o,--output", syn.output, "Phantom volume")->required();
  s->add_option("--truth", syn.truth, "Truth label volume")->required();
  s->add_option("--size", syn_size, "Voxels NX,NY,NZ")->default_val("160,192,160");
  s->add_option("--spacing", syn_spacing, "Voxel size in mm SX,SY,SZ")->default_val("1,1,1");
  s->add_option("--noise", syn.phantom.noise, "Rician noise sd / white-matter intensity")->default_val(0.03)
      ->check(fest::cli::range(0.0, 10.0));
  s->add_option("--bias", syn.phantom.bias, "Bias field peak-to-peak")->default_val(0.2)
      ->check(fest::cli::range(0.0, 2.0));
  s->add_option("--seed", syn.phantom.seed, "Random seed")->default_val(1);

  SlicesArgs sl;
  auto* sv = app.add_subcommand("slices", "PNG of three orthogonal slices (axial, coronal, sagittal; neurological: the patient's left on the left), "
                                          "with orientation letters, a scale bar and the labels overlaid when --labels is given");
  sv->add_option("input", sl.input, "The volume that was segmented")->required();
  sv->add_option("--labels", sl.labels, "Its label volume (from segbrain run), overlaid in colour (default: none, plain grey slices)");
  sv->add_option("-o,--output", sl.output, "PNG output (- = stdout)")->default_val("-");
  sv->add_option("--kb", sl.kb, "Knowledge base whose label/4 facts give the colours")->allow_extra_args(false);
  sv->add_option("--scale", sl.scale, "Pixels per smallest voxel size")->default_val(2)->check(fest::cli::range(0.25, 8.0));

  EvalArgs ev;
  std::string ev_map, ev_ref_map;
  auto* e = app.add_subcommand("eval", "Dice, Jaccard and volume difference of a segmentation against a reference");
  e->add_option("--ref", ev.ref, "Reference label volume")->required();
  e->add_option("--seg", ev.seg, "Segmentation label volume (- = stdin)")->required();
  e->add_option("--map", ev_map, "Objects of the segmentation: \"name=v1,v2,a-b;...\" (default: nonzero)");
  e->add_option("--ref-map", ev_ref_map, "Objects of the reference, same syntax (default: --map)");

  return fest::cli::run(app, argc, argv, [&]() -> int {
    if (*k) return run_kb_check(kbc);
    if (*o) return run_ops(ops);
    if (*s) {
      syn.phantom.size = positive_counts(syn_size, "--size");
      syn.phantom.spacing = positive_lengths(syn_spacing, "--spacing");
      return run_synth(syn);
    }
    if (*e) {
      ev.map = object_map(ev_map, "--map");
      ev.ref_map = object_map(ev_ref_map.empty() ? ev_map : ev_ref_map, "--ref-map");
      return run_eval(ev);
    }
    if (*sv) return run_slices(sl);
    // run, named or implied
    if (!run_text.to.empty()) run.to = volume_output_format(run_text.to);
    for (const std::string& t : run_text.sets) run.sets.push_back(fact_setting(t));
    run.objects = object_names(run_text.objects);
    run.quiet = common.quiet;
    run.verbose = common.verbose;
    return run_segment(run);
  });
}

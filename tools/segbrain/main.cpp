// segbrain: knowledge-based extraction of head and brain from MRI head volumes
// (Ehricke, seed 000 chapter 2; docs/segbrain.md). This file only declares the flags.

#include <cstring>
#include <vector>

#include "cli/cli.hpp"
#include "commands.hpp"

using namespace segbrain_tool;

int main(int argc, char** argv) {
  CLI::App app{"Rule-based extraction of head and brain from T1 MRI head volumes: a Prolog-subset\n"
               "knowledge base drives operators, verification and retries; every decision is traced.",
               "segbrain"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 goal failed or limit hit, 2 usage error, 3 bad input or KB error,\n"
             "4 I/O error. See segbrain(1).");

  RunArgs run;
  auto* r = app.add_subcommand("run", "Segment a volume (the default subcommand); the label volume to standard output or -o");
  r->fallthrough();  // -q/-v of the main command also after "run"
  r->add_option("input", run.input, "Input volume (NIfTI .nii/.nii.gz, NRRD, MHA; - = stdin)")->default_val("-");
  r->add_option("-i", run.input, "Alias of the input argument");
  r->add_option("-o,--output", run.output, "Label volume output (- = stdout)")->default_val("-");
  r->add_option("--to", run.to, "Output format: nii | nii.gz | nrrd | mha (default from -o, else nii)");
  r->add_option("--kb", run.kb, "Knowledge-base file(s) instead of the built-in head_t1.pl")->allow_extra_args(false);
  r->add_option("--goal", run.goal, "Goal to prove")->default_val("segment_head");
  r->add_option("--set", run.sets, "NAME=VALUE: replace candidates/2, limit/2 or NAME/1 facts")->allow_extra_args(false);
  r->add_option("--objects", run.objects, "Comma-separated objects to find (head, brain, ventricles, cerebellum, brainstem, eyes, optic_nerve); "
                 "proves segment_objects([...]) instead of --goal");
  r->add_option("--masks", run.masks, "Also write each emitted object as DIR/<name>.nii.gz (uint8 0/1)");
  r->add_option("--label-table", run.label_table, "Write the label colour table (index name R G B A) of the knowledge base");
  r->add_option("--report", run.report, "Write a JSON report");
  r->add_option("--trace", run.trace, "Write the proof trace as JSON lines");
  r->add_option("--modality", run.modality, "Contrast of the input: t1 | t2 | pd (the knowledge base must support it; "
                 "the built-in one supports t1)")->default_val("t1")->check(CLI::IsMember({"t1", "t2", "pd"}));
  r->add_flag("--tissue", run.tissue, "Also label grey (4) and white matter (5) inside the brain");
  r->add_option("--max-depth", run.max_depth, "Deepest proof")->default_val(10000);
  r->add_option("--max-inferences", run.max_inferences, "Most inferences")->default_val(1e7);
  r->add_option("--time-limit", run.time_limit, "Seconds (0 = none)")->default_val(0);
  fest::cli::add_threads(*r, run.threads);

  KbCheckArgs kbc;
  auto* k = app.add_subcommand("kb-check", "Lint knowledge-base files: syntax, undefined predicates, singletons");
  k->add_option("files", kbc.files, "Rule files (none = the built-in head_t1.pl)")->allow_extra_args(false);

  bool ops_json = false;
  auto* o = app.add_subcommand("ops", "List the operator predicates and their modes");
  o->add_flag("--json", ops_json, "As JSON");

  SynthArgs syn;
  auto* s = app.add_subcommand("synth", "Write the synthetic T1 head phantom and its truth labels");
  s->add_option("-o,--output", syn.output, "Phantom volume")->required();
  s->add_option("--truth", syn.truth, "Truth label volume")->required();
  s->add_option("--size", syn.size, "Voxels NX,NY,NZ")->default_val("160,192,160");
  s->add_option("--spacing", syn.spacing, "Voxel size in mm SX,SY,SZ")->default_val("1,1,1");
  s->add_option("--noise", syn.noise, "Rician noise sd / white-matter intensity")->default_val(0.03);
  s->add_option("--bias", syn.bias, "Bias field peak-to-peak")->default_val(0.2);
  s->add_option("--seed", syn.seed, "Random seed")->default_val(1);

  SlicesArgs sl;
  auto* sv = app.add_subcommand("slices", "PNG of three orthogonal slices (axial, coronal, sagittal) with the labels overlaid");
  sv->add_option("input", sl.input, "The volume that was segmented")->required();
  sv->add_option("--labels", sl.labels, "Its label volume (from segbrain run)")->required();
  sv->add_option("-o,--output", sl.output, "PNG output (- = stdout)")->default_val("-");
  sv->add_option("--kb", sl.kb, "Knowledge base whose label/4 facts give the colours")->allow_extra_args(false);
  sv->add_option("--scale", sl.scale, "Pixels per smallest voxel size")->default_val(2)->check(CLI::Range(0.25, 8.0));

  EvalArgs ev;
  auto* e = app.add_subcommand("eval", "Dice, Jaccard and volume difference of a segmentation against a reference");
  e->add_option("--ref", ev.ref, "Reference label volume")->required();
  e->add_option("--seg", ev.seg, "Segmentation label volume (- = stdin)")->required();
  e->add_option("--map", ev.map, "Objects of the segmentation: \"name=v1,v2,a-b;...\" (default: nonzero)");
  e->add_option("--ref-map", ev.ref_map, "Objects of the reference, same syntax (default: --map)");

  // `segbrain IN ...` means `segbrain run IN ...` (spec §4): without a subcommand name
  // anywhere on the line, "run" is implied unless help or the version is asked for.
  std::vector<char*> args(argv, argv + argc);
  bool named = false, meta = false;
  for (int i = 1; i < argc; ++i) {
    for (const char* sub : {"run", "kb-check", "ops", "synth", "eval", "slices"}) named = named || std::strcmp(argv[i], sub) == 0;
    for (const char* m : {"-h", "--help", "--version"}) meta = meta || std::strcmp(argv[i], m) == 0;
  }
  static char run_word[] = "run";
  if (!named && !meta && argc > 1) args.insert(args.begin() + 1, run_word);

  return fest::cli::run(app, static_cast<int>(args.size()), args.data(), [&]() -> int {
    if (*r) {
      run.quiet = common.quiet;
      return run_segment(run);
    }
    if (*k) return run_kb_check(kbc);
    if (*o) return run_ops(ops_json);
    if (*s) return run_synth(syn);
    if (*e) return run_eval(ev);
    if (*sv) return run_slices(sl);
    return 2;
  });
}

// ebcode: triangle mesh -> .ebm (Edgebreaker connectivity, quantised predicted
// positions), or Draco for comparison; `ebcode model` prints the chapter's state machines
// (docs/ebcode.md). Flags only; the commands live in cmd_*.cpp (fest_ebcode_app).

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Compress a triangle mesh into an .ebm stream: Edgebreaker connectivity with the conditional-unity\n"
               "coder (< 3.525 bits per vertex for genus 0) or an adaptive one, quantised parallelogram-predicted\n"
               "positions; non-manifold input, holes, handles and several components are kept exactly.",
               "ebcode"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(0, 1);
  using namespace fest::ebcode_tool;
  EncodeOptions opt;
  std::string conn = "auto", model = "m236", box, predict = "para", to = "ebm";
  bool no_stitch = false, no_geometry = false, no_verify = false;
  app.add_option("input", opt.input, "Input mesh (PLY, OFF, OBJ, STL, Draco), or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--conn", conn, "Connectivity coder: auto (smaller of static and adaptive), static, adaptive, raw")
      ->default_val("auto");
  app.add_option("--model", model, "Static state machine: m2, m26, m68, m236, m240x")->default_val("m236");
  app.add_option("--qp", opt.qp, "Position bits 1..30; 0 = lossless float32")->default_val(14)->check(fest::cli::range(0, 30));
  app.add_option("--qn", opt.qn, "Vertex normal bits per component (over [-1, 1])")->default_val(10)->check(fest::cli::range(1, 30));
  app.add_option("--qt", opt.qt, "Texture coordinate bits (over their own box)")->default_val(12)->check(fest::cli::range(1, 30));
  app.add_option("--box", box, "Quantisation box X,Y,Z,EXT instead of the bounding box");
  app.add_option("--predict", predict, "Position predictor: para, multi (mean of all parallelograms), delta, none")->default_val("para");
  app.add_flag("--no-stitch", no_stitch, "Keep the copies of non-manifold vertices as separate vertices");
  app.add_flag("--drop-isolated", opt.drop_isolated, "Drop vertices no face uses");
  app.add_flag("--no-geometry", no_geometry, "Connectivity only");
  app.add_flag("--strict", opt.strict, "Degenerate faces, non-manifold input and boundaries are errors");
  app.add_option("--to", to, "Output: ebm, or drc (Draco through libdraco, for comparison)")->default_val("ebm");
  app.add_option("--draco-cl", opt.draco_cl, "Draco compression level 0..10 for --to drc")
      ->default_val(7)->check(fest::cli::range(0, 10));
  app.add_option("--report", opt.report, "Write counts, bits per section, errors and times as JSON to this file");
  app.add_flag("--symbols", opt.symbols, "Write the forward CLERS string instead of the stream");
  app.add_flag("--no-verify", no_verify, "Skip re-encoding the decoded connectivity (the cheap check stays)");
  app.add_option("--ebm-version", opt.ebm_version, "Container version: 2 (compact, the default) or 1 (for readers before fest 0.2)")
      ->default_val(2)->check(fest::cli::range(1, 2));
  app.add_option("--geom-version", opt.geom_version,
                 "Position coding in a version 2 container: 0 the smaller of 3 (.ebm 2.1) and 2 (.ebm 2.0, for readers before 2.1), or 2 or 3")
      ->default_val(0)->check(fest::cli::range(0, 3));

  ModelOptions mopt;
  std::string mmodel, mto = "tsv", lmax = "-", pmax = "-", smax = "-";
  CLI::App* sub = app.add_subcommand("model", "Print a state machine of the chapter: alpha, rate, unities, frequencies");
  sub->add_option("--model", mmodel, "A named model (m2, m26, m68, m236, m240x) instead of the limits");
  sub->add_option("--lmax", lmax, "Longest tracked current-loop length, or -")->default_val("-");
  sub->add_option("--pmax", pmax, "Longest tracked top-loop length, or -")->default_val("-");
  sub->add_option("--smax", smax, "Longest tracked second-loop length, or -")->default_val("-");
  sub->add_option("--cmax", mopt.cmax, "Number of exclusion patterns used (0..19)")->default_val(19)->check(fest::cli::range(0, 19));
  sub->add_flag("--all-patterns", mopt.all_patterns, "Also the two patterns starting with EE (m240x)");
  sub->add_flag("--literal-rule", mopt.literal, "C excluded only when the history itself is a pattern (diagnostic)");
  sub->add_option("--to", mto, "tsv, json, or inc (the committed tables of all named models)")->default_val("tsv");
  app.footer("Exit status: 0 success, 1 self-verification failed, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See ebcode(1), ebdecode(1), ebm(5).");
  return fest::cli::run(app, argc, argv, [&] {
    if (sub->parsed()) {
      if (!mmodel.empty()) mopt.model = fest::edgebreaker::named_model(mmodel);
      mopt.lmax = parse_length_limit(lmax, "--lmax");
      mopt.pmax = parse_length_limit(pmax, "--pmax");
      mopt.smax = parse_length_limit(smax, "--smax");
      mopt.format = parse_model_format(mto);
      return model_command(mopt);
    }
    opt.conn = parse_conn(conn);
    opt.model = fest::edgebreaker::named_model(model);
    if (!box.empty()) opt.box = parse_box(box);
    opt.predictor = parse_predictor(predict);
    opt.format = parse_encode_format(to);
    opt.stitch = !no_stitch;
    opt.geometry = !no_geometry;
    opt.verify = !no_verify;
    opt.quiet = common.quiet;
    return encode_command(opt);
  });
}

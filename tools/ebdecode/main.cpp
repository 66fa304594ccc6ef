// ebdecode: .ebm (or Draco .drc) -> triangle mesh (docs/ebdecode.md). Flags only; the
// command lives in cmd_decode.cpp (fest_ebdecode_app).

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Decode an .ebm stream (or a Draco .drc file) into a triangle mesh.\n"
               "Vertices come in the coder's order (ebm(5)); faces keep their orientation.",
               "ebdecode"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  using namespace fest::ebdecode_tool;
  DecodeOptions opt;
  std::string to;
  bool no_stitch = false, no_verify = false;
  app.add_option("input", opt.input, "Input .ebm or .drc, or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--to", to, "Output format: ply (binary, the default), plya (ascii PLY), obj, off");
  app.add_flag("--info", opt.info, "Print the .ebm header as JSON (after checking the CRC) instead of decoding");
  app.add_option("--report", opt.report, "Write counts and decode time as JSON to this file");
  app.add_flag("--no-stitch", no_stitch, "Keep the copies of non-manifold vertices separate");
  app.add_flag("--no-verify", no_verify, "Skip re-encoding the decoded connectivity");
  app.footer("Exit status: 0 success, 2 usage error, 3 bad input (bad magic, version, CRC, truncated), 4 I/O error.\n"
             "See ebdecode(1), ebcode(1), ebm(5).");
  return fest::cli::run(app, argc, argv, [&] {
    if (!to.empty()) parse_output_format(to, opt);
    opt.stitch = !no_stitch;
    opt.verify = !no_verify;
    return decode_command(opt);
  });
}

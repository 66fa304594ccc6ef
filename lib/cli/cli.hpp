#pragma once
// The command-line conventions every fest tool shares (README "Conventions", "How every tool
// behaves"), on top of CLI11. Include only from tools/*/main.cpp.
//
//   int main(int argc, char** argv) {
//     CLI::App app{"one-line description", "tool"};
//     fest::cli::Common common;
//     fest::cli::add_common(app, common);
//     ... app.add_option(...) ...
//     return fest::cli::run(app, argc, argv, [&] { ...; return 0; });
//   }

#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/number_range.hpp"
#include "core/error.hpp"
#include "core/error_detail.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"

#ifndef FEST_VERSION
#define FEST_VERSION "0"
#endif

namespace fest::cli {

struct Common {
  bool quiet = false;
  bool verbose = false;
  bool progress = false;
};

// --progress on a command with a stage longer than about two seconds: a bar on standard
// error, drawn anyway when standard error is a terminal unless -q (core/progress.hpp
// progress_wanted: an explicit --progress wins over -q).
inline void add_progress(CLI::App& app, bool& progress) {
  app.add_flag("--progress", progress,
               "Progress bar on standard error, even with -q (default: on a terminal, unless -q)");
}

inline void add_common(CLI::App& app, Common& common, bool with_progress = false) {
  app.set_version_flag("--version", std::string(app.get_name()) + " (fest) " FEST_VERSION);
  app.add_flag("-q,--quiet", common.quiet, "Print nothing but errors");
  app.add_flag("-v,--verbose", common.verbose, "Describe what is being done on standard error");
  if (with_progress) add_progress(app, common.progress);
  app.get_formatter()->column_width(28);
}

// --threads N, checked as it is parsed: a negative or implausible count is a usage error
// worded the same by every tool (lib/core/threads' resolve_threads words it in its terms).
inline void add_threads(CLI::App& app, int& threads) {
  app.add_option("--threads", threads, "Worker threads (0 = all cores)")
      ->default_val(0)
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            int n = 0;
            if (!CLI::detail::lexical_cast(text, n)) return {};  // CLI11's own conversion error follows
            if (n < 0) throw usage_error("--threads must be 0 (all cores) or positive, not {}", n);
            if (n > max_plausible_threads) throw usage_error("--threads {} is not a plausible thread count", n);
            return {};
          },
          ""));
}

// Parses argv; help and --version go to standard output with status 0; a usage error is
// one line on standard error and status 2 (README "Conventions"), not CLI11's own codes.
// A check that throws fest::Error itself (add_threads) is reported like the body's errors.
// Every floating-point flag then obeys check_numbers (number_range.hpp): no NaN, no
// infinity unless the flag says it takes one.
template <typename Body>
int run(CLI::App& app, int argc, char** argv, Body&& body) {
  const std::string tool = app.get_name();
  return run_tool(tool, [&]() -> int {
    try {
      app.parse(argc, argv);
      if (const CLI::Option* verbose = app.get_option_no_throw("--verbose"); verbose != nullptr && verbose->count() > 0)
        show_error_details(true);
      if (const CLI::Option* quiet = app.get_option_no_throw("--quiet"); quiet != nullptr && quiet->count() > 0)
        set_progress_quiet(true);  // -q hides the automatic bar; --progress still draws it
      check_numbers(app);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
      std::fprintf(stderr, "%s: error: %s (see %s --help)\n", tool.c_str(), e.what(), tool.c_str());
      return static_cast<int>(Status::usage);
    }
    return body();
  });
}

}  // namespace fest::cli

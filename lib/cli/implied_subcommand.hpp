#pragma once
// A subcommand that a command line without one means: `segbrain IN ...` is `segbrain run
// IN ...`, `markerpose IMAGE ...` is `markerpose detect IMAGE ...`. The main command
// carries the subcommand's flags too (main.cpp adds them to both with one function, the
// main command's copies passed here), so that CLI11 parses either spelling; this shows
// the copies under a heading of their own and, after parsing, keeps the old rules of the
// spelling with the word: those copies are refused when a subcommand is named (they stood
// before it, or a second positional spilled into them), and `required` flags are needed
// when none is named. Include only from tools/*/main.cpp.

#include <algorithm>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace fest::cli {

// `bare_needs_subcommand`: an empty command line is CLI11's "A subcommand is required"
// rather than the implied subcommand reading standard input.
inline void imply_subcommand(CLI::App& app, std::vector<CLI::Option*> copies, const std::string& heading,
                             std::vector<std::string> required, bool bare_needs_subcommand) {
  for (CLI::Option* o : copies) o->group(heading);
  app.require_subcommand(0, 1);
  app.final_callback([&app, copies, required, bare_needs_subcommand] {
    if (app.get_subcommands().empty()) {
      const auto options = app.get_options();
      if (bare_needs_subcommand && std::none_of(options.begin(), options.end(), [](const CLI::Option* o) { return o->count() > 0; }))
        throw CLI::RequiredError::Subcommand(1);
      for (const std::string& flag : required)
        if (app.get_option(flag)->count() == 0) throw CLI::RequiredError(flag);
      return;
    }
    std::vector<std::string> stray;
    for (CLI::Option* o : copies)
      if (o->count() > 0) {
        if (o->get_positional()) stray.insert(stray.end(), o->results().begin(), o->results().end());
        else stray.push_back(o->get_name());
      }
    std::reverse(stray.begin(), stray.end());  // CLI11 lists them last first
    if (!stray.empty()) throw CLI::ExtrasError(stray);
  });
}

}  // namespace fest::cli

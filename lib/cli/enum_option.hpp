#pragma once
// A flag whose words name the values of an enum: `--start rtin|lattice` fills a
// StartRule. The words are checked like CLI::IsMember (same message, same help text),
// and only the words are accepted (not the enum's numbers, as CLI::CheckedTransformer
// would). Include only from tools/*/main.cpp.
//
//   fest::cli::enum_words(cmd->add_option("--start", opts.start, "..."),
//                         {{"rtin", StartRule::rtin}, {"lattice", StartRule::lattice}});

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/word_choice.hpp"

namespace fest::cli {

template <class E>
CLI::Option* enum_words(CLI::Option* option, std::vector<std::pair<std::string, E>> words) {
  std::string names;
  for (const auto& w : words) names += (names.empty() ? "" : ",") + w.first;
  option->transform(CLI::Validator(
      [words, names](std::string& input) -> std::string {
        for (const auto& w : words)
          if (w.first == input) {
            input = std::to_string(static_cast<long long>(w.second));
            return {};
          }
        return input + " not in {" + names + "}";
      },
      "value in {" + names + "}"));
  option->type_name("TEXT");
  return option;
}

// A flag whose word is checked as it is parsed, worded "FLAG: unknown 'word' (w1, w2, ...)"
// (exit 2) where a tool's tests assert that text; the value it names goes to `target`.
//
//   fest::cli::word_option(*cmd, "--outside", opts.outside, {{"none", Outside::none}, {"clamp", Outside::clamp}}, "...");
template <class T>
CLI::Option* word_option(CLI::App& app, const std::string& flag, T& target, std::vector<std::pair<std::string, T>> words,
                         const std::string& help) {
  return app.add_option_function<std::string>(
      flag, [&target, words, flag](const std::string& word) { target = word_choice(word, words, flag.c_str(), ""); },
      help);
}

}  // namespace fest::cli

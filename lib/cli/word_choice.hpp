#pragma once
// A flag's word -> the value it names, for flags read by hand after CLI11 parsed them (the
// tool's own option helpers); CLI11 flags use enum_words (enum_option.hpp) instead. Light:
// no CLI11, so a tool's library may include it.

#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace fest::cli {

// The value a word names, for a flag read by hand (after CLI11): a usage error
// "FLAG: unknown NOUN 'word' (w1, w2, ...)" when it names none ("FLAG: unknown 'word'
// (...)" when the noun is empty). The words are listed in the order given.
template <class T>
T word_choice(const std::string& word, const std::vector<std::pair<std::string, T>>& words, const char* flag,
              const char* noun) {
  std::string names;
  for (const auto& w : words) {
    if (w.first == word) return w.second;
    names += (names.empty() ? "" : ", ") + w.first;
  }
  if (!*noun) throw usage_error("{}: unknown '{}' ({})", flag, word, names);
  throw usage_error("{}: unknown {} '{}' ({})", flag, noun, word, names);
}

}  // namespace fest::cli

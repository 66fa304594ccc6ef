#pragma once
// "Did you mean ...?" for unknown keys and names in scene, case and option files.

#include <string>
#include <vector>

namespace fest {

// The candidate nearest to `word` by Levenshtein distance, or "" when none is within
// max(2, |word| / 3) edits (a hint that far off would mislead more than help).
std::string closest_word(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace fest

#pragma once
// JSON documents compared as data: numbers by absolute difference, everything else
// (keys, array lengths, strings, booleans, types) must match exactly.

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace fest::compare {

struct JsonDifference {
  double max_abs = 0;                  // over numbers at the same place in both documents
  std::size_t numbers = 0;             // how many number pairs were compared
  std::size_t structural = 0;          // places that differ in kind, key set, length or text
  std::string first_structural_path;   // JSON pointer of the first such place ("/a/3/b")
};

JsonDifference json_difference(const nlohmann::json& a, const nlohmann::json& b);

}  // namespace fest::compare

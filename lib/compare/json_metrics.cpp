#include <algorithm>
#include <cmath>

#include "compare/json_compare.hpp"

namespace fest::compare {

namespace {

void walk(const nlohmann::json& a, const nlohmann::json& b, const std::string& path, JsonDifference& d) {
  auto structural = [&] {
    if (d.structural++ == 0) d.first_structural_path = path.empty() ? "/" : path;
  };
  if (a.is_number() && b.is_number()) {
    d.max_abs = std::max(d.max_abs, std::abs(a.get<double>() - b.get<double>()));
    ++d.numbers;
    return;
  }
  if (a.type() != b.type()) {
    structural();
    return;
  }
  if (a.is_object()) {
    for (const auto& [key, value] : a.items()) {
      const auto other = b.find(key);
      if (other == b.end())
        structural();
      else
        walk(value, *other, path + "/" + key, d);
    }
    for (const auto& [key, value] : b.items())
      if (!a.contains(key)) structural();
    return;
  }
  if (a.is_array()) {
    if (a.size() != b.size()) structural();
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) walk(a[i], b[i], path + "/" + std::to_string(i), d);
    return;
  }
  if (a != b) structural();
}

}  // namespace

JsonDifference json_difference(const nlohmann::json& a, const nlohmann::json& b) {
  JsonDifference d;
  walk(a, b, "", d);
  return d;
}

}  // namespace fest::compare

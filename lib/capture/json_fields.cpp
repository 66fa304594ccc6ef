#include "capture/json_fields.hpp"

#include <algorithm>
#include <cmath>

#include "core/closest_word.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::capture {

std::string json_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

void JsonFields::fail(const std::string& what, const std::string& path) const {
  throw bad_input("{}: {} ({})", path.empty() ? "document" : path, what, where_);
}

void JsonFields::keys(const nlohmann::json& object, const std::string& path, const std::vector<std::string>& allowed) const {
  if (!object.is_object()) fail("must be a JSON object", path);
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    const std::string hint = closest_word(key, allowed);
    fail(hint.empty() ? fmt::format("unknown key \"{}\"", quoted_bytes(key))
                      : fmt::format("unknown key \"{}\" (did you mean \"{}\"?)", quoted_bytes(key), hint),
         path);
  }
}

double JsonFields::number(const nlohmann::json& v, const std::string& path, double lo, double hi) const {
  if (!v.is_number()) fail("must be a number", path);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) fail(fmt::format("must be a number in [{}, {}]", lo, hi), path);
  return x;
}

double JsonFields::positive(const nlohmann::json& v, const std::string& path) const {
  if (!v.is_number()) fail("must be a positive number", path);
  const double x = v.get<double>();
  if (!std::isfinite(x) || !(x > 0)) fail("must be a positive number", path);
  return x;
}

int JsonFields::integer(const nlohmann::json& v, const std::string& path, int lo, int hi) const {
  if (!v.is_number_integer() && !v.is_number_unsigned()) fail(fmt::format("must be an integer in [{}, {}]", lo, hi), path);
  const long long x = v.get<long long>();
  if (x < lo || x > hi) fail(fmt::format("must be an integer in [{}, {}]", lo, hi), path);
  return int(x);
}

bool JsonFields::boolean(const nlohmann::json& v, const std::string& path) const {
  if (!v.is_boolean()) fail("must be true or false", path);
  return v.get<bool>();
}

std::string JsonFields::string(const nlohmann::json& v, const std::string& path) const {
  if (!v.is_string() || v.get<std::string>().empty()) fail("must be a non-empty string", path);
  return v.get<std::string>();
}

std::vector<std::string> JsonFields::strings(const nlohmann::json& v, const std::string& path) const {
  if (!v.is_array()) fail("must be an array of strings", path);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(string(v[i], fmt::format("{}[{}]", path, i)));
  return out;
}

std::vector<double> JsonFields::numbers(const nlohmann::json& v, const std::string& path, std::size_t n) const {
  if (!v.is_array() || (n > 0 && v.size() != n) || v.empty())
    fail(n > 0 ? fmt::format("must be an array of {} numbers", n) : "must be a non-empty array of numbers", path);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], fmt::format("{}[{}]", path, i), -1e300, 1e300));
  return out;
}

std::array<double, 3> JsonFields::vec3(const nlohmann::json& v, const std::string& path) const {
  const std::vector<double> x = numbers(v, path, 3);
  return {x[0], x[1], x[2]};
}

std::array<double, 9> JsonFields::mat3(const nlohmann::json& v, const std::string& path) const {
  std::array<double, 9> m{};
  if (v.is_array() && v.size() == 3 && v[0].is_array()) {
    for (std::size_t r = 0; r < 3; ++r) {
      const std::array<double, 3> row = vec3(v[r], fmt::format("{}[{}]", path, r));
      for (std::size_t c = 0; c < 3; ++c) m[3 * r + c] = row[c];
    }
    return m;
  }
  const std::vector<double> x = numbers(v, path, 9);
  std::copy(x.begin(), x.end(), m.begin());
  return m;
}

}  // namespace fest::capture

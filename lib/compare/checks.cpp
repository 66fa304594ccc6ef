#include "compare/checks.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::compare {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::string format_value(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "nan";
  return fmt::format("{:.9g}", v);
}

}  // namespace

Check parse_threshold(const std::string& text) {
  std::size_t pos = text.find("<=");
  bool at_most = true;
  if (pos == std::string::npos) {
    pos = text.find(">=");
    at_most = false;
  }
  if (pos == std::string::npos)
    throw usage_error("threshold '{}' is not METRIC<=VALUE or METRIC>=VALUE", text);
  Check c;
  c.metric = trim(text.substr(0, pos));
  c.at_most = at_most;
  const std::string value = trim(text.substr(pos + 2));
  const std::string quoted = quoted_bytes(text, 40);
  char* end = nullptr;
  errno = 0;
  c.limit = std::strtod(value.c_str(), &end);
  if (c.metric.empty() || value.empty() || *end != '\0')
    throw usage_error("threshold '{}' is not METRIC<=VALUE or METRIC>=VALUE", quoted);
  // A limit compares with a measured number: NaN compares false with everything and an
  // infinity (or a value strtod overflows to one, 1e999) passes or fails every finite
  // measurement; say so instead of a check that means nothing.
  if (std::isnan(c.limit) || std::isinf(c.limit) || (errno == ERANGE && std::abs(c.limit) > 1))
    throw usage_error("threshold '{}': the value must be a finite number (at most about 1.8e308 in size), not {}",
                      quoted, quoted_bytes(value, 24));
  return c;
}

nlohmann::json json_number(double v) {
  if (!std::isfinite(v)) return nullptr;
  return v;
}

void Metrics::set(const std::string& name, double value) {
  for (auto& [n, v] : values_) {
    if (n == name) {
      v = value;
      return;
    }
  }
  values_.emplace_back(name, value);
}

void Metrics::family(const std::vector<std::string>& metrics) { families_.push_back(metrics); }

bool Metrics::same_family(const std::string& a, const std::string& b) const {
  if (a == b) return true;
  for (const auto& f : families_)
    if (std::find(f.begin(), f.end(), a) != f.end() && std::find(f.begin(), f.end(), b) != f.end()) return true;
  return false;
}

void Metrics::require(const std::string& metric, const std::string& op, double limit) {
  checks_.push_back({{metric, op == "<=", limit}, false});
}

void Metrics::require(const Check& check) {
  checks_.erase(std::remove_if(checks_.begin(), checks_.end(),
                               [&](const Entry& e) {
                                 return e.check.metric == check.metric ||
                                        (!e.asked && same_family(e.check.metric, check.metric));
                               }),
                checks_.end());
  checks_.push_back({check, true});
}

const double* Metrics::find(const std::string& name) const {
  for (const auto& [n, v] : values_)
    if (n == name) return &v;
  return nullptr;
}

std::vector<std::string> Metrics::evaluate() const {
  std::vector<std::string> failures;
  for (const Entry& e : checks_) {
    const Check& c = e.check;
    const double* v = find(c.metric);
    if (v == nullptr) {
      std::string known;
      for (const auto& [n, value] : values_) known += (known.empty() ? "" : ", ") + n;
      throw usage_error("no metric '{}' for these files (measured: {})", c.metric, known);
    }
    // NaN fails every check: an undefined error is not a small one.
    const bool ok = c.at_most ? (*v <= c.limit) : (*v >= c.limit);
    if (!ok)
      failures.push_back(fmt::format("{} = {} {} {}", c.metric, format_value(*v),
                                     c.at_most ? "exceeds" : "is below", format_value(c.limit)));
  }
  return failures;
}

std::string Metrics::summary() const {
  std::string out;
  for (const auto& [n, v] : values_) out += n + " " + format_value(v) + "\n";
  return out;
}

nlohmann::json Metrics::to_json() const {
  nlohmann::json metrics = nlohmann::json::object();
  for (const auto& [n, v] : values_) metrics[n] = json_number(v);
  nlohmann::json checks = nlohmann::json::array();
  bool pass = true;
  for (const Entry& e : checks_) {
    const Check& c = e.check;
    const double* v = find(c.metric);
    const bool ok = v && (c.at_most ? (*v <= c.limit) : (*v >= c.limit));
    pass = pass && ok;
    checks.push_back({{"metric", c.metric},
                      {"op", c.at_most ? "<=" : ">="},
                      {"limit", json_number(c.limit)},
                      {"value", v ? json_number(*v) : nlohmann::json(nullptr)},
                      {"pass", ok},
                      {"default", !e.asked}});
  }
  return {{"metrics", metrics}, {"checks", checks}, {"details", details}, {"pass", pass}};
}

}  // namespace fest::compare

#pragma once
// Named metrics and the checks applied to them ("hausdorff <= 1e-6", "psnr >= 40"):
// what fcompare reports and how it decides its exit status.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace fest::compare {

struct Check {
  std::string metric;
  bool at_most = true;  // "<=" when true, ">=" otherwise
  double limit = 0;
};

// Parses "metric<=value" or "metric>=value" (spaces allowed). Throws Status::usage.
Check parse_threshold(const std::string& text);

// +inf/-inf/NaN are not JSON numbers: they become null.
nlohmann::json json_number(double v);

class Metrics {
 public:
  void set(const std::string& name, double value);
  // A default check; replaced by a later require(Check) on the same metric.
  void require(const std::string& metric, const std::string& op, double limit);
  // A check the user asked for: replaces every earlier check on that metric.
  void require(const Check& check);

  // The failed checks as "metric = value exceeds limit" lines. Throws Status::usage when
  // a check names a metric that was not measured (the message lists those that were).
  std::vector<std::string> evaluate() const;

  // "name value" lines in the order the metrics were set.
  std::string summary() const;
  nlohmann::json to_json() const;

  nlohmann::json details = nlohmann::json::object();  // per-channel, per-label, topology...

 private:
  const double* find(const std::string& name) const;
  std::vector<std::pair<std::string, double>> values_;
  std::vector<Check> checks_;
};

}  // namespace fest::compare

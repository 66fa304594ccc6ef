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

// How a check the user asks for (fcompare -t) meets the defaults:
//  * it replaces every earlier check on the same metric, default or not;
//  * it also replaces the DEFAULT checks on every metric of the same family, because
//    metrics of one family measure one thing in different units (an image's max_abs,
//    rmse and psnr), so a default on one of them would contradict the user's criterion
//    on another ("psnr>=40" means "some error is fine", which "max_abs<=0" denies);
//  * checks the user asked for are never replaced by another family member.
class Metrics {
 public:
  void set(const std::string& name, double value);
  // Declares that these metrics measure the same thing (see above).
  void family(const std::vector<std::string>& metrics);
  // A default check; replaced by a later require(Check) on the same metric or family.
  void require(const std::string& metric, const std::string& op, double limit);
  // A check the user asked for: replaces every earlier check on that metric and the
  // default checks of its family.
  void require(const Check& check);

  // The failed checks as "metric = value exceeds limit" lines. Throws Status::usage when
  // a check names a metric that was not measured (the message lists those that were).
  std::vector<std::string> evaluate() const;

  // "name value" lines in the order the metrics were set.
  std::string summary() const;
  nlohmann::json to_json() const;

  nlohmann::json details = nlohmann::json::object();  // per-channel, per-label, topology...

 private:
  struct Entry {
    Check check;
    bool asked = false;  // from the user, not a default
  };
  const double* find(const std::string& name) const;
  bool same_family(const std::string& a, const std::string& b) const;
  std::vector<std::pair<std::string, double>> values_;
  std::vector<Entry> checks_;
  std::vector<std::vector<std::string>> families_;
};

}  // namespace fest::compare

#pragma once
// The analytic self-checks of `fluidsim check` (docs/fluidsim.md §7): each returns a JSON
// report with the measured figures, the thresholds (from the mathematics) and "pass".

#include <nlohmann/json.hpp>

namespace fest::fluidsim {

struct CheckOptions {
  int n = 0;          // 0: the case's default resolution(s)
  double dt = 0.0;    // 0: the case's default
  double nu = 0.01;
};

nlohmann::json check_projection(const CheckOptions& o);
nlohmann::json check_taylor_green(const CheckOptions& o);
nlohmann::json check_abc(const CheckOptions& o);
nlohmann::json check_mass(const CheckOptions& o);
nlohmann::json check_stability(const CheckOptions& o);
nlohmann::json check_interp(const CheckOptions& o);

}  // namespace fest::fluidsim

#pragma once
// The validation cases of `lbmsim check` (docs/lbmsim.md 3): each runs the solver on a
// case whose answer is known from mathematics or a published table and returns a JSON
// report {"case", "metrics", "criteria", "pass"}.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/progress_callback.hpp"

namespace fest::lbm {

struct CheckOptions {
  int n = 0;  // resolution where a case has one (cavity N, cylinder D); 0: the default
  // Thousandths of the case: runs done (a case of fixed runs), or, for a case run to a
  // steady state, how far its change has fallen towards the tolerance on a log scale (or
  // its steps towards the limit, whichever is further).
  ProgressFn progress;
};

nlohmann::json check_poiseuille(const CheckOptions& o);
nlohmann::json check_taylor_green(const CheckOptions& o);
nlohmann::json check_cavity(const CheckOptions& o, double re);
nlohmann::json check_cylinder(const CheckOptions& o);
nlohmann::json check_mass(const CheckOptions& o);
nlohmann::json check_symmetry(const CheckOptions& o);
nlohmann::json check_determinism(const CheckOptions& o);

// Case names of `lbmsim check`, and the members of all-fast.
const std::vector<std::string>& check_names();
const std::vector<std::string>& fast_checks();
nlohmann::json run_check(const std::string& name, const CheckOptions& o);

// Ghia, Ghia & Shin (1982), u/U on the vertical centre line and v/U on the horizontal
// one: 17 rows of {coordinate, Re 100, Re 400, Re 1000}.
extern const double kGhiaU[17][4];
extern const double kGhiaV[17][4];

}  // namespace fest::lbm

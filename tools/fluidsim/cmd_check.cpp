// fluidsim check: the analytic cases of docs/fluidsim.md -> one JSON report.
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "fluidsim/checks.hpp"
#include "openmp_threads.hpp"

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;
using nlohmann::json;

int check_command(const CheckOptions& o) {
  set_threads(o.threads);
  fluidsim::CheckOptions co;
  co.n = o.n;
  co.dt = o.dt;
  co.nu = o.nu;
  json report;
  const std::string& w = o.which;
  auto run_one = [&](const std::string& name) {
    if (name == "projection") return check_projection(co);
    if (name == "taylor-green") return check_taylor_green(co);
    if (name == "abc") return check_abc(co);
    if (name == "mass") return check_mass(co);
    if (name == "stability") return check_stability(co);
    return check_interp(co);
  };
  if (w == "all") {
    report = {{"check", "all"}, {"cases", json::array()}};
    bool pass = true;
    for (const char* name : {"projection", "taylor-green", "abc", "mass", "stability", "interp"}) {
      json r = run_one(name);
      pass = pass && r["pass"].get<bool>();
      report["cases"].push_back(r);
    }
    report["pass"] = pass;
  } else {
    report = run_one(w);
  }
  const std::string text = report.dump(2) + "\n";
  if (!o.report.empty()) write_output(o.report, text);
  write_output("-", text);
  return report["pass"].get<bool>() ? 0 : 1;
}

}  // namespace fest::fluidsim_tool

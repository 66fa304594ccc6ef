// fluidsim check: the analytic cases of docs/fluidsim.md -> one JSON report.
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
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
  auto run_one = [&](CheckCase which) {
    switch (which) {
      case CheckCase::projection: return check_projection(co);
      case CheckCase::taylor_green: return check_taylor_green(co);
      case CheckCase::abc: return check_abc(co);
      case CheckCase::mass: return check_mass(co);
      case CheckCase::stability: return check_stability(co);
      default: return check_interp(co);
    }
  };
  const std::vector<CheckCase> cases = o.which == CheckCase::all
                                            ? std::vector<CheckCase>{CheckCase::projection, CheckCase::taylor_green,
                                                                     CheckCase::abc, CheckCase::mass, CheckCase::stability,
                                                                     CheckCase::interp}
                                            : std::vector<CheckCase>{o.which};
  Progress bar("fluidsim check", cases.size(), progress_wanted(o.progress));
  if (o.which == CheckCase::all) {
    report = {{"check", "all"}, {"cases", json::array()}};
    bool pass = true;
    for (const CheckCase which : cases) {
      json r = run_one(which);
      bar.advance();
      pass = pass && r["pass"].get<bool>();
      report["cases"].push_back(r);
    }
    report["pass"] = pass;
  } else {
    report = run_one(o.which);
  }
  bar.finish();
  const std::string text = report.dump(2) + "\n";
  if (!o.report.empty()) write_output(o.report, text);
  write_output("-", text);
  return report["pass"].get<bool>() ? 0 : 1;
}

}  // namespace fest::fluidsim_tool

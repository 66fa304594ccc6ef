// lbmsim check: a validation case -> JSON report, exit 1 when it fails.
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "lbm/checks.hpp"

namespace fest::lbmsim_tool {

using nlohmann::json;

int check_command(const CheckOptions& o) {
  lbm::CheckOptions co;
  co.n = o.n;
  Progress bar("lbmsim check", 0, progress_wanted(o.progress));
  co.progress = bar.callback();
  const json report = lbm::run_check(o.which, co);
  bar.finish();
  const std::string text = report.dump(2) + "\n";
  if (!o.report.empty()) write_output(o.report, text);
  write_output("-", text);
  return report["pass"].get<bool>() ? 0 : 1;
}

}  // namespace fest::lbmsim_tool

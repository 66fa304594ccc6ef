// fcompare's job: read both files, measure, check, report. Exit 0 when every check
// holds, 1 when one fails.

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

int compare_command(const CompareOptions& opt) {
  const Input a = load_input(opt.a);
  const Input b = load_input(opt.b);
  const Kind kind = kind_of(a.format);
  if (kind != kind_of(b.format))
    throw bad_input("cannot compare a {} ({}) with a {} ({})", kind_name(kind), a.name, kind_name(kind_of(b.format)),
                    b.name);

  Metrics m;
  measure(a, b, opt, m);
  for (const compare::Check& t : opt.thresholds) m.require(t);

  const auto failures = m.evaluate();
  if (!opt.report.empty()) {
    nlohmann::json report = m.to_json();
    report["a"] = a.name;
    report["b"] = b.name;
    report["kind"] = kind_name(kind);
    write_output(opt.report, report.dump(2) + "\n");
  }
  if (!opt.quiet) write_output("-", m.summary());
  for (const auto& f : failures)
    std::fprintf(stderr, "fcompare: %s (%s, %s)\n", f.c_str(), a.name.c_str(), b.name.c_str());
  return failures.empty() ? 0 : static_cast<int>(Status::failure);
}

}  // namespace fest::fcompare_tool

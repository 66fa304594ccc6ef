// fcompare on JSON documents: numbers and structure.

#include <nlohmann/json.hpp>

#include "compare/json_compare.hpp"
#include "formats/table/table_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

void compare_json(const Input& ia, const Input& ib, const CompareOptions& opt, Metrics& m) {
  const auto d = compare::json_difference(parse(ia, read_json_document), parse(ib, read_json_document));
  m.set("max_abs", d.max_abs);
  m.set("structural_diffs", static_cast<double>(d.structural));
  m.details["numbers"] = d.numbers;
  if (d.structural > 0) m.details["first_structural_diff"] = d.first_structural_path;
  require_main(m, "max_abs", opt);
  m.require("structural_diffs", "<=", 0);
}

}  // namespace fest::fcompare_tool

// fcompare on tables: max abs and max rel per column.

#include <nlohmann/json.hpp>

#include "compare/table_compare.hpp"
#include "formats/table/table_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

void compare_tables(const formats::Input& ia, const formats::Input& ib, const CompareOptions& opt,
                    compare::Metrics& m) {
  const auto [a, b] = parse_both(ia, ib, formats::read_table);
  const auto e = compare::table_error(a, b);
  m.set("max_abs", e.max_abs);
  m.set("max_rel", e.max_rel);
  nlohmann::json cols = nlohmann::json::object();
  for (const auto& c : e.columns) cols[c.name] = {{"max_abs", c.max_abs}, {"max_rel", c.max_rel}};
  m.details["columns"] = cols;
  m.family({"max_abs", "max_rel"});
  require_main(m, "max_abs", opt);
}

}  // namespace fest::fcompare_tool

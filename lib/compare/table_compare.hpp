#pragma once
// Table differences: the largest absolute difference per column.

#include <string>
#include <vector>

#include "core/table.hpp"

namespace fest::compare {

struct ColumnError {
  std::string name;
  double max_abs = 0;
  double max_rel = 0;  // |a-b| / max(|a|,|b|), 0 where both are 0
};

struct TableError {
  std::vector<ColumnError> columns;
  double max_abs = 0;
  double max_rel = 0;
};

// Columns are matched by name; the same names and row count are required (throws
// Status::failure otherwise). NaN equals NaN; NaN against a number is +inf.
TableError table_error(const Table& a, const Table& b);

}  // namespace fest::compare

#include <cmath>
#include <limits>

#include "compare/table_compare.hpp"
#include "core/error.hpp"

namespace fest::compare {

TableError table_error(const Table& a, const Table& b) {
  if (a.rows() != b.rows()) throw runtime_failure("row counts differ: {} and {}", a.rows(), b.rows());
  if (a.cols() != b.cols()) throw runtime_failure("column counts differ: {} and {}", a.cols(), b.cols());
  TableError out;
  for (std::size_t c = 0; c < a.cols(); ++c) {
    const std::size_t cb = b.find(a.names[c]);
    if (cb == Table::npos) throw runtime_failure("column '{}' is missing from the second table", a.names[c]);
    ColumnError col{a.names[c], 0, 0};
    for (std::size_t r = 0; r < a.rows(); ++r) {
      const double x = a.columns[c][r], y = b.columns[cb][r];
      double diff, rel;
      if (std::isnan(x) || std::isnan(y)) {
        diff = (std::isnan(x) && std::isnan(y)) ? 0.0 : std::numeric_limits<double>::infinity();
        rel = diff;
      } else if (x == y) {  // also equal infinities
        diff = rel = 0;
      } else {
        diff = std::abs(x - y);
        rel = diff / std::max(std::abs(x), std::abs(y));
      }
      col.max_abs = std::max(col.max_abs, diff);
      col.max_rel = std::max(col.max_rel, rel);
    }
    out.max_abs = std::max(out.max_abs, col.max_abs);
    out.max_rel = std::max(out.max_rel, col.max_rel);
    out.columns.push_back(col);
  }
  return out;
}

}  // namespace fest::compare

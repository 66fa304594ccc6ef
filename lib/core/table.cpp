#include "core/table.hpp"

#include "core/error.hpp"

namespace fest {

std::size_t Table::find(const std::string& name) const noexcept {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  return npos;
}

void Table::add_column(std::string name, std::vector<double> values) {
  if (find(name) != npos) throw bad_input("duplicate column name '{}'", name);
  if (!columns.empty() && values.size() != rows())
    throw bad_input("column '{}' has {} rows, the table has {}", name, values.size(), rows());
  names.push_back(std::move(name));
  columns.push_back(std::move(values));
}

}  // namespace fest

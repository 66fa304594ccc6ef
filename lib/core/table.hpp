#pragma once
// Rows of named numeric columns: the in-memory form of CSV/TSV files (column-major,
// because every consumer so far works on whole columns).

#include <cstddef>
#include <string>
#include <vector>

namespace fest {

struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;  // columns[c][row]; all the same length

  std::size_t rows() const noexcept { return columns.empty() ? 0 : columns.front().size(); }
  std::size_t cols() const noexcept { return columns.size(); }
  // Index of the column with this name, or npos.
  std::size_t find(const std::string& name) const noexcept;
  // Appends a column; throws Status::bad_input when its length differs from the others
  // or the name is already taken.
  void add_column(std::string name, std::vector<double> values);

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

}  // namespace fest

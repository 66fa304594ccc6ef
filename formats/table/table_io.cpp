#include "formats/table/table_io.hpp"
#include "core/quote.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::formats {

namespace {

struct Dialect {
  char delimiter;
  const char* name;  // "CSV" / "TSV" in messages
};

Dialect dialect_of(Format format) {
  if (format == Format::csv) return {',', "CSV"};
  if (format == Format::tsv) return {'\t', "TSV"};
  throw bad_input("{} is not a table format (csv or tsv)", format_name(format));
}

// Cut long cell text in messages: a fuzzed line can be megabytes.
std::string excerpt(std::string_view s) { return fest::quoted_bytes(s, 40); }

std::string_view trim_blanks(std::string_view s, char delimiter) noexcept {
  auto blank = [delimiter](char c) { return (c == ' ' || c == '\t') && c != delimiter; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Splits one line into cells. A cell may be quoted ("a, ""b""" per RFC 4180), which is
// how names containing the delimiter are written; quoted cells do not span lines.
std::vector<std::string> split_cells(std::string_view line, const Dialect& d, std::size_t line_number) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  for (;;) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t') && line[i] != d.delimiter) ++i;
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      const std::size_t open = i++;
      for (;;) {
        if (i >= line.size())
          throw bad_input("{} line {}, column {}: the quote opened at character {} is not closed", d.name, line_number,
                          cells.size() + 1, open + 1);
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t') && line[i] != d.delimiter) ++i;
      if (i < line.size() && line[i] != d.delimiter)
        throw bad_input("{} line {}, column {}: text after the closing quote", d.name, line_number, cells.size() + 1);
    } else {
      const std::size_t end = std::min(line.find(d.delimiter, i), line.size());
      cell = std::string(trim_blanks(line.substr(i, end - i), d.delimiter));
      i = end;
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) break;
    ++i;  // past the delimiter; a trailing delimiter makes one more (empty) cell
  }
  return cells;
}

// A numeric cell: decimal or scientific, nan, inf; empty means NaN (a missing value).
bool parse_cell(const std::string& cell, double& value) {
  if (cell.empty()) {
    value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  std::string_view s = cell;
  if (s.front() == '+') s.remove_prefix(1);
  const auto res = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || res.ptr != s.data() + s.size()) return false;
  if (res.ec == std::errc::result_out_of_range) {
    // Overflow is +-inf and underflow 0 (or a subnormal), as strtod gives them.
    value = std::strtod(cell.c_str(), nullptr);
    return true;
  }
  return res.ec == std::errc();
}

bool needs_quotes(const std::string& name, char delimiter) {
  if (name.empty()) return false;
  if (name.front() == '#' || name.front() == ' ' || name.back() == ' ' || name.front() == '\t' || name.back() == '\t') return true;
  for (char c : name)
    if (c == delimiter || c == '"' || c == '\n' || c == '\r') return true;
  return false;
}

std::string quoted(const std::string& name) {
  std::string out = "\"";
  for (char c : name) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

Table read_table(std::string_view bytes, Format format) {
  const Dialect d = dialect_of(format);
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // a UTF-8 byte order mark
  std::size_t pos = 0, line_number = 0;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  bool have_header = false;
  while (pos < bytes.size()) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? bytes.size() : nl;
    std::string_view line = bytes.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? bytes.size() : nl + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // Blank lines carry no row (a one-column NaN is written "nan", not left empty).
    if (trim_blanks(line, d.delimiter).empty()) continue;
    if (!have_header) {
      if (line.front() == '#') continue;  // comments are allowed before the header
      names = split_cells(line, d, line_number);
      for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (names[i] == names[j])
            throw bad_input("{} header (line {}): column {} repeats the name '{}'", d.name, line_number, i + 1, excerpt(names[i]));
      columns.resize(names.size());
      have_header = true;
      continue;
    }
    const std::vector<std::string> cells = split_cells(line, d, line_number);
    if (cells.size() != names.size())
      throw bad_input("{} line {}: {} cells, the header names {} columns", d.name, line_number, cells.size(), names.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double value = 0;
      if (!parse_cell(cells[c], value))
        throw bad_input("{} line {}, column {} ('{}'): '{}' is not a number", d.name, line_number, c + 1,
                        excerpt(names[c]), excerpt(cells[c]));
      columns[c].push_back(value);
    }
  }
  if (!have_header) throw bad_input("{}: no header line with column names", d.name);
  Table table;
  table.names = std::move(names);
  table.columns = std::move(columns);
  return table;
}

std::string write_table(const Table& table, Format format) {
  const Dialect d = dialect_of(format);
  if (table.names.size() != table.columns.size())
    throw bad_input("table has {} names for {} columns", table.names.size(), table.columns.size());
  const std::size_t rows = table.rows();
  for (std::size_t c = 0; c < table.cols(); ++c)
    if (table.columns[c].size() != rows)
      throw bad_input("table column '{}' has {} rows, the first has {}", excerpt(table.names[c]), table.columns[c].size(), rows);
  std::string out;
  for (std::size_t c = 0; c < table.cols(); ++c) {
    if (c > 0) out += d.delimiter;
    out += needs_quotes(table.names[c], d.delimiter) ? quoted(table.names[c]) : table.names[c];
  }
  out += '\n';
  fmt::memory_buffer buf;
  for (std::size_t r = 0; r < rows; ++r) {
    buf.clear();
    for (std::size_t c = 0; c < table.cols(); ++c) {
      if (c > 0) buf.push_back(d.delimiter);
      fmt::format_to(std::back_inserter(buf), "{}", table.columns[c][r]);
    }
    buf.push_back('\n');
    out.append(buf.data(), buf.size());
  }
  return out;
}

nlohmann::json describe_table(const Table& table) {
  nlohmann::json columns = nlohmann::json::array();
  for (std::size_t c = 0; c < table.cols(); ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    bool any = false;
    for (double v : table.columns[c]) {
      if (std::isnan(v)) continue;  // missing values
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      any = true;
    }
    nlohmann::json col;
    col["name"] = table.names[c];
    col["min"] = any ? nlohmann::json(lo) : nlohmann::json(nullptr);
    col["max"] = any ? nlohmann::json(hi) : nlohmann::json(nullptr);
    columns.push_back(std::move(col));
  }
  return {{"rows", table.rows()}, {"columns", std::move(columns)}};
}

}  // namespace fest::formats

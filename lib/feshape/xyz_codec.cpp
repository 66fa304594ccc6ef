#include "feshape/xyz_codec.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::feshape {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; }

// Splits a line into its first three fields; returns how many were found.
int first_fields(std::string_view line, std::string_view (&f)[3]) {
  int n = 0;
  std::size_t i = 0;
  while (n < 3) {
    while (i < line.size() && is_separator(line[i])) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    f[n++] = line.substr(start, i - start);
  }
  return n;
}

bool parse_number(std::string_view s, double& x) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

std::vector<Eigen::Vector3d> decode_points(std::string_view text) {
  std::vector<Eigen::Vector3d> points;
  std::size_t line_no = 0, pos = 0;
  bool seen_row = false;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    std::string_view f[3];
    const int n = first_fields(line, f);
    if (n == 0 || f[0].front() == '#') continue;
    double x[3];
    bool numeric = n == 3;
    for (int i = 0; i < n && numeric; ++i) numeric = parse_number(f[i], x[i]);
    if (!numeric) {
      double first;
      if (!seen_row && !parse_number(f[0], first)) {  // a header line of names
        seen_row = true;
        continue;
      }
      throw bad_input("point rows: line {} is not 'x y z' (three numbers)", line_no);
    }
    seen_row = true;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw bad_input("point rows: line {} has a non-finite coordinate", line_no);
    points.emplace_back(x[0], x[1], x[2]);
  }
  return points;
}

std::string encode_points(const std::vector<Eigen::Vector3d>& points) {
  std::string out;
  out.reserve(points.size() * 40);
  for (const auto& p : points) fmt::format_to(std::back_inserter(out), "{} {} {}\n", p.x(), p.y(), p.z());
  return out;
}

}  // namespace fest::feshape

// The flag values with numbers inside (seed points, seed lines, the parallel sweep),
// parsed once for main.cpp; the usage errors name the flag and quote the text.

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "core/error.hpp"

namespace fest::lemtrace_tool {
namespace {

// "x,y,z" -> three numbers; usage error otherwise.
std::vector<double> numbers(const std::string& text, std::size_t count, const char* option) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
      throw usage_error("{} '{}': '{}' is not a number", option, text, item);
    out.push_back(v);
  }
  if (out.size() != count) throw usage_error("{} '{}': expected {} numbers separated by commas", option, text, count);
  return out;
}

}  // namespace

std::array<double, 3> parse_seed_point(const std::string& text) {
  const auto v = numbers(text, 3, "--seed-point");
  return {v[0], v[1], v[2]};
}

SeedLine parse_seed_line(const std::string& l) {
  const std::size_t c1 = l.find(':'), c2 = l.find(':', c1 == std::string::npos ? c1 : c1 + 1);
  if (c1 == std::string::npos || c2 == std::string::npos)
    throw usage_error("--seed-line '{}': expected x0,y0,z0:x1,y1,z1:n", l);
  const auto p0 = numbers(l.substr(0, c1), 3, "--seed-line");
  const auto p1 = numbers(l.substr(c1 + 1, c2 - c1 - 1), 3, "--seed-line");
  const auto nn = numbers(l.substr(c2 + 1), 1, "--seed-line");
  const int n = static_cast<int>(nn[0]);
  if (n < 1 || n != nn[0] || n > 10000000) throw usage_error("--seed-line '{}': n must be a positive integer", l);
  return {{p0[0], p0[1], p0[2]}, {p1[0], p1[1], p1[2]}, n};
}

ParallelSweep parse_parallel_sweep(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw usage_error("--sweep-parallel '{}': expected FROM:TO, e.g. 1e-7:1e-1", text);
  const double from = numbers(text.substr(0, colon), 1, "--sweep-parallel")[0];
  const double upto = numbers(text.substr(colon + 1), 1, "--sweep-parallel")[0];
  if (!(from > 0 && upto >= from)) throw usage_error("--sweep-parallel '{}': need 0 < FROM <= TO", text);
  return {from, upto};
}

const char* line_format_name(LineFormat f) {
  switch (f) {
    case LineFormat::csv: return "csv";
    case LineFormat::vtp: return "vtp";
    case LineFormat::vtk: return "vtk";
    case LineFormat::json: return "json";
    case LineFormat::unset: break;
  }
  return "";
}

}  // namespace fest::lemtrace_tool

// The texts of segbrain's flags turned into its typed options (commands.hpp), for
// main.cpp; the messages name the flag.
#include <cmath>
#include <sstream>

#include "cli/number_list.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace fest::segbrain_tool {

namespace {

// Largest count along one axis: 2^31 - 1, so that every index fits the int of the
// readers and writers.
constexpr double kMaxCount = 2147483647;
constexpr double kMaxLengthMm = 1e6;

// Three positive numbers "A,B,C".
std::array<double, 3> positive_triple(const std::string& text, const char* flag) {
  const auto not_positive = [&] { return usage_error("{} expects 3 positive numbers separated by commas, got '{}'", flag, text); };
  std::vector<double> v;
  try {
    v = cli::number_list(text, 1, 0, flag);
  } catch (const Error&) {
    throw not_positive();
  }
  for (std::size_t i = 0; i < v.size() && i < 3; ++i)
    if (!(v[i] > 0)) throw not_positive();
  if (v.size() != 3) throw usage_error("{} expects 3 numbers, got '{}'", flag, text);
  return {v[0], v[1], v[2]};
}

}  // namespace

formats::OutputFormat volume_output_format(const std::string& name) {
  const formats::OutputFormat of = formats::output_format_from_name(name);
  if (formats::kind_of(of.format) != formats::Kind::volume) throw usage_error("--to: not a volume format");
  return of;
}

FactSetting fact_setting(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw usage_error("--set expects NAME=VALUE, got '{}'", text);
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::vector<std::string> object_names(const std::string& list) {
  std::vector<std::string> names;
  if (list.empty()) return names;
  std::istringstream in(list);
  std::string name;
  while (std::getline(in, name, ','))
    if (name.empty()) throw usage_error("--objects: empty object name in '{}'", list);
    else names.push_back(name);
  if (list.back() == ',') throw usage_error("--objects: empty object name in '{}'", list);
  return names;
}

std::array<std::size_t, 3> positive_counts(const std::string& text, const char* flag) {
  const std::array<double, 3> v = positive_triple(text, flag);
  // Whole counts, each small enough to convert exactly; what their product needs is
  // checked where it is allocated (cmd_synth.cpp).
  for (const double x : v)
    if (x != std::floor(x) || x > kMaxCount)
      throw usage_error("{} expects 3 whole numbers in [1, {}], got '{}'", flag, kMaxCount, text);
  return {static_cast<std::size_t>(v[0]), static_cast<std::size_t>(v[1]), static_cast<std::size_t>(v[2])};
}

std::array<double, 3> positive_lengths(const std::string& text, const char* flag) {
  const std::array<double, 3> v = positive_triple(text, flag);
  // A voxel of a kilometre is no head; the bound keeps the world extent (size x spacing) finite.
  for (const double x : v)
    if (x > kMaxLengthMm) throw usage_error("{} expects 3 lengths in (0, {}] mm, got '{}'", flag, kMaxLengthMm, text);
  return v;
}

ObjectMap object_map(const std::string& text, const char* option) {
  ObjectMap out;
  if (text.empty()) {
    out.push_back({"object", {{1, INFINITY}}});
    return out;
  }
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t semi = text.find(';', pos);
    std::string item = text.substr(pos, semi == std::string::npos ? std::string::npos : semi - pos);
    auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw usage_error("{}: expected name=values, got '{}'", option, item);
    LabelRanges ranges;
    std::string vals = item.substr(eq + 1);
    std::size_t p = 0;
    while (p <= vals.size()) {
      std::size_t comma = vals.find(',', p);
      std::string v = vals.substr(p, comma == std::string::npos ? std::string::npos : comma - p);
      auto dash = v.find('-', 1);
      try {
        if (dash == std::string::npos) ranges.push_back({std::stod(v), std::stod(v)});
        else ranges.push_back({std::stod(v.substr(0, dash)), std::stod(v.substr(dash + 1))});
      } catch (const std::exception&) {
        throw usage_error("{}: bad label value '{}'", option, v);
      }
      if (comma == std::string::npos) break;
      p = comma + 1;
    }
    out.push_back({item.substr(0, eq), ranges});
    if (semi == std::string::npos) break;
    pos = semi + 1;
  }
  return out;
}

}  // namespace fest::segbrain_tool

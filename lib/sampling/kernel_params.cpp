#include "sampling/kernel_params.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"

namespace fest::sampling {

namespace {

std::string keys_of(const std::map<std::string, double>& defaults) {
  std::string out;
  for (const auto& kv : defaults) out += (out.empty() ? "" : ", ") + kv.first;
  return out.empty() ? "none" : out;
}

// Whole-string decimal number; false for trailing junk or an empty string.
bool parse_decimal(const std::string& s, double& value) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return errno == 0 && end == s.c_str() + s.size() && std::isfinite(value);
}

bool parse_number(const std::string& s, double& value) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) return parse_decimal(s, value);
  double p = 0, q = 0;
  if (!parse_decimal(s.substr(0, slash), p) || !parse_decimal(s.substr(slash + 1), q) || q == 0)
    return false;
  value = p / q;
  return true;
}

}  // namespace

KernelSpelling split_kernel_spelling(std::string_view spec) {
  const auto colon = spec.find(':');
  if (colon == std::string_view::npos) return {std::string(spec), ""};
  return {std::string(spec.substr(0, colon)), std::string(spec.substr(colon + 1))};
}

std::map<std::string, double> parse_kernel_params(std::string_view kernel, std::string_view text,
                                                  const std::map<std::string, double>& defaults) {
  std::map<std::string, double> values = defaults;
  std::size_t pos = 0;
  while (pos < text.size()) {
    auto comma = text.find(',', pos);
    if (comma == std::string_view::npos) comma = text.size();
    const std::string pair(text.substr(pos, comma - pos));
    pos = comma + 1;
    const auto eq = pair.find('=');
    if (eq == std::string::npos)
      throw usage_error("kernel '{}': parameter '{}' is not key=value (keys: {})", kernel, pair,
                        keys_of(defaults));
    const std::string key = pair.substr(0, eq);
    if (!defaults.count(key))
      throw usage_error("kernel '{}' has no parameter '{}' (keys: {})", kernel, key, keys_of(defaults));
    double v = 0;
    if (!parse_number(pair.substr(eq + 1), v))
      throw usage_error("kernel '{}': '{}' is not a finite number", kernel, pair);
    values[key] = v;
  }
  return values;
}

}  // namespace fest::sampling

// Output names from printf-style patterns ("out/f%05d.vti"): exactly one integer
// conversion, flags '0' and a width only, so a pattern cannot inject other conversions.
#include <cctype>

#include <fmt/format.h>

#include "output_names.hpp"
#include "core/error.hpp"

namespace fest::fluidsim_tool {

namespace {
// Position and length of the conversion, or npos; throws for a malformed pattern.
std::pair<std::size_t, std::size_t> find_conversion(const std::string& p) {
  std::size_t found = std::string::npos, len = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] != '%') continue;
    if (i + 1 < p.size() && p[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j]))) ++j;
    if (j >= p.size() || p[j] != 'd' || j - i > 4)
      throw usage_error("output pattern \"{}\" may hold only one %d-style conversion (%d, %05d)", p);
    if (found != std::string::npos) throw usage_error("output pattern \"{}\" holds more than one %d", p);
    found = i;
    len = j - i + 1;
    i = j;
  }
  return {found, len};
}
}  // namespace

bool has_index_conversion(const std::string& pattern) {
  return find_conversion(pattern).first != std::string::npos;
}

std::string expand_pattern(const std::string& pattern, long index) {
  const auto [pos, len] = find_conversion(pattern);
  std::string out;
  auto unescape = [](const std::string& s) {
    std::string r;
    for (std::size_t i = 0; i < s.size(); ++i) {
      r += s[i];
      if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
    }
    return r;
  };
  if (pos == std::string::npos) return unescape(pattern);
  const std::string spec = pattern.substr(pos + 1, len - 2);
  const bool zero = !spec.empty() && spec[0] == '0';
  const int width = spec.empty() ? 0 : std::stoi(spec);
  const std::string number = zero ? fmt::format("{:0{}d}", index, width) : fmt::format("{:{}d}", index, width);
  return unescape(pattern.substr(0, pos)) + number + unescape(pattern.substr(pos + len));
}

}  // namespace fest::fluidsim_tool

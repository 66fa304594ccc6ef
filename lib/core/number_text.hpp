#pragma once
// Numbers appended to text with std::to_chars: no iostreams, no locale, no allocation
// per number. append_g17 writes exactly what printf("%.17g") (and fmt's "{:.17g}")
// writes, digits, trailing-zero removal and exponent form included, so text outputs can
// move to it without changing a byte; 17 significant digits round-trip every double.

#include <charconv>
#include <cstdint>
#include <string>

namespace fest {

inline void append_g17(std::string& out, double x) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
  out.append(buf, r.ptr);
}

inline void append_int(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace fest

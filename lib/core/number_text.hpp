#pragma once
// Numbers appended to text without iostreams, locale or allocation per number.
// append_g17 writes exactly what printf("%.17g") (and fmt's "{:.17g}") writes, digits,
// trailing-zero removal and exponent form included, so text outputs can move to it
// without changing a byte; 17 significant digits round-trip every double.

#include <charconv>
#include <cstdint>
#include <string>

namespace fest {

// Writes x as "%.17g" at `out` (at least 32 bytes free); returns the end.
char* write_g17(char* out, double x) noexcept;

inline void append_g17(std::string& out, double x) {
  char buf[40];
  out.append(buf, write_g17(buf, x));
}

inline void append_int(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace fest

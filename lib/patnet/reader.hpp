#pragma once
// The PaT-Lisp reader (docs/patnet.md "Language"): bytes -> data with source positions.
// Hand-written over bytes; fuzzed by tests/fuzz/fuzz_patnet.cpp.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fest::patnet {

struct SrcPos {
  int file = 0;  // index into the machine's list of loaded file names
  int line = 0;  // 1-based; 0 = no position (built by the program)
  int col = 0;   // 1-based, in bytes
};

// One datum as read: a list, a symbol (upper-cased, keywords keep their ':'), or an atom.
struct Datum {
  enum class Kind { list, symbol, integer, real, string };
  Kind kind = Kind::list;
  SrcPos pos;
  std::string text;  // symbol name (upper case) or string contents
  std::int64_t i = 0;
  double d = 0.0;
  std::vector<Datum> items;

  bool is_symbol(std::string_view name) const { return kind == Kind::symbol && text == name; }
  bool is_list() const { return kind == Kind::list; }
};

// A syntax error: message and position (the caller adds the file name).
struct ReadError {
  std::string message;
  SrcPos pos;
};

// Reads every top-level datum of `src`. Throws ReadError on unbalanced parentheses, an
// unterminated string, a malformed number or nesting deeper than `max_depth`.
std::vector<Datum> read_all(std::string_view src, int file, int max_depth = 1000);

// Lisp's upper-casing of symbol names (ASCII only: names are case-insensitive).
std::string upcase(std::string_view s);

}  // namespace fest::patnet

// The PaT-Lisp reader: ';' comments, symbols (case-insensitive), ':keywords', integers,
// floats, strings with \" and \\ escapes, 'x = (quote x), #'f = (function f).

#include "patnet/reader.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/text_position.hpp"

namespace fest::patnet {

std::string upcase(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

namespace {

class Reader {
 public:
  Reader(std::string_view src, int file, int max_depth) : s_(src), file_(file), max_depth_(max_depth) {}

  std::vector<Datum> all() {
    std::vector<Datum> out;
    for (;;) {
      skip_space();
      if (at_end()) return out;
      if (peek() == ')') fail("unbalanced ')'", here());
      out.push_back(datum(0));
    }
  }

 private:
  std::string_view s_;
  int file_;
  int max_depth_;
  std::size_t p_ = 0;
  TextPosition pos_;

  bool at_end() const { return p_ >= s_.size(); }
  char peek() const { return s_[p_]; }
  SrcPos here() const { return SrcPos{file_, pos_.line, pos_.col}; }
  char next() {
    const char c = s_[p_++];
    pos_.advance(c);
    return c;
  }
  [[noreturn]] static void fail(std::string msg, SrcPos pos) { throw ReadError{std::move(msg), pos}; }

  void skip_space() {
    while (!at_end()) {
      const char c = peek();
      if (c == ';') {
        while (!at_end() && peek() != '\n') next();
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        next();
      } else {
        return;
      }
    }
  }

  static bool delimiter(char c) {
    return std::isspace(static_cast<unsigned char>(c)) || c == '(' || c == ')' || c == '"' || c == ';' || c == '\'';
  }

  Datum wrap(const char* head, SrcPos pos, int depth) {
    Datum d;
    d.kind = Datum::Kind::list;
    d.pos = pos;
    Datum h;
    h.kind = Datum::Kind::symbol;
    h.pos = pos;
    h.text = head;
    d.items.push_back(std::move(h));
    skip_space();
    if (at_end()) fail(std::string("nothing after ") + (head[0] == 'Q' ? "'" : "#'"), pos);
    if (peek() == ')') fail("')' right after a quote", here());
    d.items.push_back(datum(depth + 1));
    return d;
  }

  Datum datum(int depth) {
    if (depth > max_depth_) fail("nesting deeper than " + std::to_string(max_depth_) + " levels", here());
    const SrcPos pos = here();
    const char c = peek();
    if (c == '(') {
      next();
      Datum d;
      d.kind = Datum::Kind::list;
      d.pos = pos;
      for (;;) {
        skip_space();
        if (at_end()) fail("unbalanced '(': end of file inside this list", pos);
        if (peek() == ')') {
          next();
          return d;
        }
        d.items.push_back(datum(depth + 1));
      }
    }
    if (c == '\'') {
      next();
      return wrap("QUOTE", pos, depth);
    }
    if (c == '#') {
      next();
      if (at_end() || peek() != '\'') fail("'#' must be followed by a quote (#'function)", pos);
      next();
      return wrap("FUNCTION", pos, depth);
    }
    if (c == '"') {
      next();
      Datum d;
      d.kind = Datum::Kind::string;
      d.pos = pos;
      for (;;) {
        if (at_end()) fail("unterminated string", pos);
        char ch = next();
        if (ch == '"') return d;
        if (ch == '\\') {
          if (at_end()) fail("unterminated string", pos);
          ch = next();
        }
        d.text.push_back(ch);
      }
    }
    // An atom: a number if it parses as one completely, else a symbol.
    const std::size_t start = p_;
    while (!at_end() && !delimiter(peek())) {
      if (peek() == '#' ) fail("'#' inside a symbol", here());
      next();
    }
    const std::string tok(s_.substr(start, p_ - start));
    Datum d;
    d.pos = pos;
    if (number(tok, d)) return d;
    d.kind = Datum::Kind::symbol;
    d.text = upcase(tok);
    return d;
  }

  static bool number(const std::string& tok, Datum& d) {
    const char c0 = tok[0];
    const bool sign = c0 == '+' || c0 == '-';
    if (!(std::isdigit(static_cast<unsigned char>(c0)) || ((sign || c0 == '.') && tok.size() > 1))) return false;
    bool digit = false, other = false, real = false;
    for (char ch : tok) {
      if (std::isdigit(static_cast<unsigned char>(ch))) digit = true;
      else if (ch == '.' || ch == 'e' || ch == 'E') real = true;
      else if (ch != '+' && ch != '-') other = true;
    }
    if (!digit || other) return false;
    errno = 0;
    char* end = nullptr;
    if (!real) {
      const long long v = std::strtoll(tok.c_str(), &end, 10);
      if (*end == '\0' && errno == 0) {
        d.kind = Datum::Kind::integer;
        d.i = v;
        return true;
      }
      if (*end == '\0' && errno == ERANGE) real = true;  // too big for 64 bits: a float
      else return false;
    }
    errno = 0;
    const double v = std::strtod(tok.c_str(), &end);
    if (*end != '\0' || !std::isfinite(v)) return false;
    d.kind = Datum::Kind::real;
    d.d = v;
    return true;
  }
};

}  // namespace

std::vector<Datum> read_all(std::string_view src, int file, int max_depth) {
  return Reader(src, file, max_depth).all();
}

}  // namespace fest::patnet

#pragma once
// Input text as it may appear in a message: a few bytes, escaped. A reader that quotes
// what it found ("\"x\" is not a number") must not copy control characters, bytes that are
// not UTF-8 or a whole binary block onto the user's terminal (issue 31: one line a person
// can read). Also the words fest uses for a JSON library's failure.

#include <cstddef>
#include <string>
#include <string_view>

namespace fest {

// `text` with control bytes, DEL and every byte that is not
// part of well-formed UTF-8 written as \xNN, and cut after `max` input bytes with "...".
// Well-formed multi-byte UTF-8 sequences pass through whole (a name in Greek stays legible).
inline std::string quoted_bytes(std::string_view text, std::size_t max = 24) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  const std::size_t n = text.size() < max ? text.size() : max;
  auto escape = [&](unsigned char c) {
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
  };
  std::size_t i = 0;
  while (i < n) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    // Length of a well-formed UTF-8 sequence starting here (0 = not one).
    std::size_t len = 0;
    if (c >= 0xc2 && c <= 0xdf) len = 2;
    else if (c >= 0xe0 && c <= 0xef) len = 3;
    else if (c >= 0xf0 && c <= 0xf4) len = 4;
    bool ok = len > 0 && i + len <= n;
    for (std::size_t k = 1; ok && k < len; ++k)
      ok = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (ok && len == 3) {  // no overlong forms, no surrogates
      const auto c1 = static_cast<unsigned char>(text[i + 1]);
      ok = !(c == 0xe0 && c1 < 0xa0) && !(c == 0xed && c1 >= 0xa0);
    } else if (ok && len == 4) {
      const auto c1 = static_cast<unsigned char>(text[i + 1]);
      ok = !(c == 0xf0 && c1 < 0x90) && !(c == 0xf4 && c1 >= 0x90);
    }
    if (ok) {
      out.append(text.substr(i, len));
      i += len;
    } else {
      escape(c);
      ++i;
    }
  }
  if (text.size() > max) out += "...";
  return out;
}

// Line and column (from 1) of byte `offset` (from 0) in `text`.
struct LineColumn {
  std::size_t line = 1, column = 1;
};
inline LineColumn line_column_at(std::string_view text, std::size_t offset) {
  LineColumn at;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++at.line;
      at.column = 1;
    } else {
      ++at.column;
    }
  }
  return at;
}

// A JSON library failure in fest's words. `what` is the library's exception text (its
// "[json.exception.x.N]" tag, its "last read: '...'" quotation of raw input and its
// wording are not passed on); `byte` is the parse error's 1-based byte count, or 0 for an
// error that is not about the syntax (a missing key, a value of the wrong type); `text`
// is the document, for the line and column. Gives e.g.
//   "not JSON: invalid literal at line 3, column 7 (byte 31)"
//   "expected a number, got a string"      "field 'levels' missing"
inline std::string json_failure_words(std::string_view what, std::size_t byte,
                                      std::string_view text) {
  if (const std::size_t close = what.find("] "); !what.empty() && what[0] == '[' &&
                                                  close != std::string_view::npos)
    what.remove_prefix(close + 2);
  if (byte > 0) {
    // "parse error at line 1, column 5: syntax error while parsing value - invalid
    // literal; last read: '...'; expected ..." -> "invalid literal"
    std::string_view reason = "malformed";
    if (const std::size_t dash = what.find(" - "); dash != std::string_view::npos) {
      reason = what.substr(dash + 3);
      reason = reason.substr(0, reason.find(';'));
    } else if (what.find("unexpected end of input") != std::string_view::npos ||
               byte > text.size()) {
      reason = "unexpected end of input";
    }
    const std::size_t offset = byte > 0 ? byte - 1 : 0;
    const LineColumn at = line_column_at(text, offset);
    return "not JSON: " + quoted_bytes(reason, 60) + " at line " + std::to_string(at.line) +
           ", column " + std::to_string(at.column) + " (byte " + std::to_string(byte) + ")";
  }
  // "type must be number, but is string" -> "expected a number, got a string"
  if (what.rfind("type must be ", 0) == 0) {
    const std::size_t but = what.find(", but is ");
    if (but != std::string_view::npos) {
      auto article = [](std::string_view w) {
        const bool vowel = !w.empty() && std::string_view("aeiou").find(w[0]) != std::string_view::npos;
        return std::string(vowel ? "an " : "a ") + std::string(w);
      };
      const std::string_view want = what.substr(13, but - 13);
      const std::string_view got = what.substr(but + 9);
      return "expected " + article(want) + ", got " + article(got);
    }
  }
  // "key 'levels' not found" -> "field 'levels' missing"
  if (what.rfind("key '", 0) == 0) {
    const std::size_t end = what.find("' not found");
    if (end != std::string_view::npos)
      return "field '" + quoted_bytes(what.substr(5, end - 5), 40) + "' missing";
  }
  return quoted_bytes(what, 80);
}

}  // namespace fest

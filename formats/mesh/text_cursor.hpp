#pragma once
// Scanning text held in memory: whitespace-separated tokens, whole lines, and
// locale-independent number parsing (std::from_chars), with line numbers for
// error messages. Shared by the PLY (ascii), OFF, OBJ and STL (ascii) readers.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fest::formats::mesh_detail {

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

class TextCursor {
 public:
  explicit TextCursor(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}

  bool at_end() const { return pos_ >= text_.size(); }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return text_.size() - pos_; }
  std::string_view rest() const { return text_.substr(pos_); }

  void skip_whitespace() {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  }
  // The next whitespace-separated token; empty at the end of the text.
  std::string_view next_token();
  // The next line without its "\n" or "\r\n"; false at the end of the text.
  bool next_line(std::string_view& line);
  // 1-based line number of the current position (counts newlines: only for messages).
  std::size_t line_number() const;

 private:
  std::string_view text_;
  std::size_t pos_;
};

// Splits one line into whitespace-separated tokens.
class LineTokens {
 public:
  explicit LineTokens(std::string_view line) : cursor_(line) {}
  std::string_view next() { return cursor_.next_token(); }
 private:
  TextCursor cursor_;
};

// The entry of a {name, ...} table whose name is `name`, or nullptr (keyword tables of
// the PLY header and the PLY reader's property roles).
template <class Entry, std::size_t N>
const Entry* find_named(const Entry (&entries)[N], std::string_view name) {
  for (const Entry& e : entries)
    if (name == e.name) return &e;
  return nullptr;
}

// Cuts a line at the first '#' (comments in OFF and OBJ).
std::string_view strip_comment(std::string_view line);

// Number parsing that accepts exactly the whole token (no trailing junk). Doubles
// accept a leading '+', "nan" and "inf"; the result is the correctly rounded value.
bool parse_double(std::string_view token, double& out);
bool parse_int64(std::string_view token, std::int64_t& out);
bool parse_uint64(std::string_view token, std::uint64_t& out);
// True for an optionally signed run of digits ("255", "-3"), false for "1.0", "1e3".
bool is_integer_literal(std::string_view token);

}  // namespace fest::formats::mesh_detail

#include "formats/mesh/text_cursor.hpp"

#include <algorithm>
#include <charconv>
#include <system_error>

namespace fest::formats::mesh_detail {

std::string_view TextCursor::next_token() {
  skip_whitespace();
  std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

bool TextCursor::next_line(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;
  return true;
}

std::size_t TextCursor::line_number() const {
  std::size_t end = std::min(pos_, text_.size());
  return 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

std::string_view strip_comment(std::string_view line) {
  std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

namespace {

// The whole token (a leading '+' dropped) as a T by std::from_chars, which takes no sign
// for unsigned types. Out of range (1e999) is malformed data rather than infinity:
// from_chars leaves `out` unchanged and reports result_out_of_range.
template <class T>
bool parse_whole(std::string_view token, T& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  auto result = std::from_chars(token.data(), end, out);
  return result.ec == std::errc() && result.ptr == end;
}

}  // namespace

bool parse_double(std::string_view token, double& out) { return parse_whole(token, out); }
bool parse_int64(std::string_view token, std::int64_t& out) { return parse_whole(token, out); }
bool parse_uint64(std::string_view token, std::uint64_t& out) { return parse_whole(token, out); }

bool is_integer_literal(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  return !token.empty() && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace fest::formats::mesh_detail

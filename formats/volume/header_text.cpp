#include "formats/volume/header_text.hpp"
#include "core/quote.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/error.hpp"

namespace fest::formats::volume_detail {

namespace {
// Values quoted in messages are cut short: a fuzzed header can have megabyte lines.
std::string excerpt(std::string_view s) { return fest::quoted_bytes(s, 40); }
}  // namespace

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::string to_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string_view> split_words(std::string_view s) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r') ++i;
    if (i > start) words.push_back(s.substr(start, i - start));
  }
  return words;
}

bool next_line(std::string_view text, std::size_t& pos, std::string_view& line) noexcept {
  if (pos >= text.size()) return false;
  const std::size_t nl = text.find('\n', pos);
  const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
  line = text.substr(pos, end - pos);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos = nl == std::string_view::npos ? text.size() : nl + 1;
  return true;
}

bool HeaderLines::next(std::string_view& line) {
  if (!next_line(text_, pos_, line)) return false;
  ++line_number_;
  if (pos_ > kMaxHeaderBytes) throw bad_input("{} header is longer than {} bytes", format_, kMaxHeaderBytes);
  return true;
}

AxisSizes parse_axis_sizes(const std::vector<std::string_view>& words, std::string_view text, std::uint64_t max_voxels,
                           const std::string& field, const char* exceed) {
  AxisSizes out;
  for (std::size_t i = 0; i < words.size() && i < out.dims.size(); ++i) {
    std::uint64_t& d = out.dims[i];
    d = parse_count(words[i], field);
    if (d == 0) throw bad_input("{}: axis {} has size 0", field, i);
    if (d > max_voxels || out.count * d > max_voxels)
      throw bad_input("{} '{}' {} the limit of {} voxels", field, fest::quoted_bytes(text, 60), exceed, max_voxels);
    out.count *= d;
  }
  return out;
}

double parse_number(std::string_view word, const std::string& field) {
  std::string_view w = trim(word);
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  double v = 0;
  const auto res = std::from_chars(w.data(), w.data() + w.size(), v);
  if (w.empty() || res.ec != std::errc() || res.ptr != w.data() + w.size())
    throw bad_input("{}: '{}' is not a number", field, excerpt(word));
  return v;
}

std::int64_t parse_integer(std::string_view word, const std::string& field) {
  std::string_view w = trim(word);
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  std::int64_t v = 0;
  const auto res = std::from_chars(w.data(), w.data() + w.size(), v);
  if (res.ec == std::errc::result_out_of_range) throw bad_input("{}: '{}' is out of range", field, excerpt(word));
  if (w.empty() || res.ec != std::errc() || res.ptr != w.data() + w.size())
    throw bad_input("{}: '{}' is not an integer", field, excerpt(word));
  return v;
}

std::uint64_t parse_count(std::string_view word, const std::string& field) {
  const std::int64_t v = parse_integer(word, field);
  if (v < 0) throw bad_input("{}: {} is negative", field, v);
  return static_cast<std::uint64_t>(v);
}

std::vector<double> parse_numbers(std::string_view value, std::size_t n, const std::string& field) {
  const std::vector<std::string_view> words = split_words(value);
  if (words.size() != n) throw bad_input("{}: {} numbers expected, found {}", field, n, words.size());
  std::vector<double> out;
  out.reserve(n);
  for (std::string_view w : words) out.push_back(parse_number(w, field));
  return out;
}

}  // namespace fest::formats::volume_detail

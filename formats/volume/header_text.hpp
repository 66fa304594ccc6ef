#pragma once
// Small parsers for the "key: value" / "Key = Value" text headers of NRRD and MetaImage.
// Every function is strict (the whole word must be a number) and throws bad_input with
// the caller's description of the field, so messages say what and where.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats::volume_detail {

// Headers longer than this are refused: real ones are a few hundred bytes, and the bound
// keeps a file of one endless header line from being scanned field by field.
constexpr std::size_t kMaxHeaderBytes = 1 << 20;

std::string_view trim(std::string_view s) noexcept;
std::string to_lower(std::string_view s);
std::vector<std::string_view> split_words(std::string_view s);  // on spaces and tabs

// A text line starting at `pos`: the line without its "\n" or "\r\n", and `pos` moved
// past the newline. Returns false at the end of the text.
bool next_line(std::string_view text, std::size_t& pos, std::string_view& line) noexcept;

// The lines of a text header from `pos` on, counted for messages; `next` refuses (bad
// input naming `format`) a header that runs past kMaxHeaderBytes.
class HeaderLines {
 public:
  HeaderLines(std::string_view text, std::size_t pos, std::size_t lines_before, const char* format)
      : text_(text), pos_(pos), line_number_(lines_before), format_(format) {}
  bool next(std::string_view& line);
  std::size_t line_number() const noexcept { return line_number_; }
  std::size_t position() const noexcept { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_number_;
  const char* format_;
};

// One header field: its key in lower case and the member of Header that keeps its value
// (several keys may name one member: MetaImage's Offset/Position/Origin).
template <class Header>
struct HeaderField {
  const char* key;
  std::optional<std::string> Header::*value;
};

// Keeps `value` in the member `fields` names for `key`; false when no field has that key.
template <class Header, std::size_t N>
bool store_field(Header& header, const HeaderField<Header> (&fields)[N], std::string_view key, std::string value) {
  for (const HeaderField<Header>& f : fields)
    if (key == f.key) {
      header.*f.value = std::move(value);
      return true;
    }
  return false;
}

double parse_number(std::string_view word, const std::string& field);
std::uint64_t parse_count(std::string_view word, const std::string& field);  // >= 0
std::int64_t parse_integer(std::string_view word, const std::string& field);
// The sizes of a header's axes ("NRRD sizes", "MetaImage DimSize": `field`), one word
// each: every size at least 1, their product (count) at most max_voxels. Unused axes of
// the four stay 1. `exceed` is the verb agreeing with `field` in the message.
struct AxisSizes {
  std::array<std::uint64_t, 4> dims{1, 1, 1, 1};
  std::uint64_t count = 1;
};
AxisSizes parse_axis_sizes(const std::vector<std::string_view>& words, std::string_view text, std::uint64_t max_voxels,
                           const std::string& field, const char* exceed);

// Exactly n numbers separated by spaces.
std::vector<double> parse_numbers(std::string_view value, std::size_t n, const std::string& field);

}  // namespace fest::formats::volume_detail

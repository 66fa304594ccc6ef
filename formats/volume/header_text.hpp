#pragma once
// Small parsers for the "key: value" / "Key = Value" text headers of NRRD and MetaImage.
// Every function is strict (the whole word must be a number) and throws bad_input with
// the caller's description of the field, so messages say what and where.

#include <array>
#include <cstdint>
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

double parse_number(std::string_view word, const std::string& field);
std::uint64_t parse_count(std::string_view word, const std::string& field);  // >= 0
std::int64_t parse_integer(std::string_view word, const std::string& field);
// Exactly n numbers separated by spaces.
std::vector<double> parse_numbers(std::string_view value, std::size_t n, const std::string& field);

}  // namespace fest::formats::volume_detail

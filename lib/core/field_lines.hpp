#pragma once
// Text of whitespace-separated fields, line by line (landmark files, batch lists): the
// one splitter, so that every such file treats blanks, comments and line numbers alike.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fest {

struct FieldLine {
  std::size_t number = 0;            // 1-based line number in the text, for messages
  std::vector<std::string> fields;   // never empty
};

// Splits `text` into lines of fields separated by spaces, tabs and carriage returns;
// with hash_comments, '#' starts a comment that runs to the end of the line. Lines
// without fields (blank, or only a comment) are dropped.
inline std::vector<FieldLine> field_lines(std::string_view text, bool hash_comments) {
  std::vector<FieldLine> lines;
  std::size_t number = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    if (hash_comments) {
      const auto hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
    }
    FieldLine l{number, {}};
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
      if (j > i) l.fields.emplace_back(line.substr(i, j - i));
      i = j;
    }
    if (!l.fields.empty()) lines.push_back(std::move(l));
  }
  return lines;
}

}  // namespace fest

#pragma once
// The lines of a text that hold more than blanks, with their numbers: the loop of the
// JSON Lines readers (events, key poses), written once.

#include <string>

namespace fest {

// Calls fn(line, text) for each line of `bytes` (split at '\n', the last one without
// it) that has a character other than space, tab or CR; lines are numbered from 1,
// blank ones included, so that "name:line" points into the file.
template <class Fn>
void for_each_nonblank_line(const std::string& bytes, Fn&& fn) {
  std::size_t start = 0;
  int line = 0;
  while (start < bytes.size()) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) end = bytes.size();
    const std::string text = bytes.substr(start, end - start);
    start = end + 1;
    ++line;
    if (text.find_first_not_of(" \t\r") != std::string::npos) fn(line, text);
  }
}

}  // namespace fest

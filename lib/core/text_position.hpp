#pragma once
// Line and column (both from 1) of a reader walking through text one character at a
// time, for the "file:line:col" of its parse errors.

namespace fest {

struct TextPosition {
  int line = 1, col = 1;
  void advance(char c) {  // past c
    if (c == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
};

}  // namespace fest

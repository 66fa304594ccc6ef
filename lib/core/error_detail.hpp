#pragma once
// A third-party library's own words behind a fest error. The message a person reads is in
// fest's words ("vtu: the offsets of the cells of piece 0 do not increase"); what the
// library said (VTK's sentence, with its class names) is kept behind it, after
// error_detail_mark, and tool_main prints it on a second line only when the tool runs with
// -v/--verbose (show_error_details). Without -v the mark and the detail are dropped.
//
// The mark is one byte that no message contains (ASCII record separator), not a newline,
// so that it passes the VTK plugin's one-line message buffer unchanged.

#include <string>
#include <string_view>
#include <utility>

namespace fest {

inline constexpr char error_detail_mark = '\x1e';

// `message` with `detail` kept behind it.
inline std::string with_error_detail(std::string message, std::string_view detail) {
  if (detail.empty()) return message;
  message += error_detail_mark;
  message.append(detail);
  return message;
}

// With true (a tool's -v/--verbose; lib/cli's run sets it), tool_main's run_tool prints an
// error's detail on a second line, "tool: detail: ..."; otherwise only fest's one-line
// message. Defined in tool_main.cpp.
void show_error_details(bool on);

// {message, detail} of a what() text; detail is empty when there is none.
inline std::pair<std::string_view, std::string_view> split_error_detail(std::string_view what) {
  const std::size_t at = what.find(error_detail_mark);
  if (at == std::string_view::npos) return {what, {}};
  return {what.substr(0, at), what.substr(at + 1)};
}

}  // namespace fest

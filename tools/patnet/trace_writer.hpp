#pragma once
// The trace on standard output (docs/patnet.md "Output"): JSON Lines (keys in a fixed
// order), TSV, or only the text of (format t ...) with --raw-print. Buffered; held back
// while files load so that a load error leaves standard output empty.

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "patnet/machine.hpp"

namespace fest::patnet_tool {

enum class TraceFormat { json, tsv, raw, none };

class TraceWriter : public patnet::TraceSink {
 public:
  TraceWriter(std::FILE* out, TraceFormat format);
  void event(const patnet::Event& e) override;
  void hold(bool h) { hold_ = h; }
  void discard() { buf_.clear(); }
  void flush();
  std::int64_t events() const { return events_; }

 private:
  std::FILE* out_;
  TraceFormat format_;
  std::string buf_;
  bool hold_ = false;
  std::int64_t events_ = 0;
  std::int64_t time_cycle_ = -1;
  std::string time_str_, detail_;
  std::vector<std::pair<std::string, std::size_t>> prefix_;  // by instance id
};

std::string json_string(std::string_view s);
std::string format_time(double t);

}  // namespace fest::patnet_tool

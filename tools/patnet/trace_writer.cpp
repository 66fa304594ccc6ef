#include "trace_writer.hpp"

#include <charconv>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::patnet_tool {

using patnet::Event;

TraceWriter::TraceWriter(std::FILE* out, TraceFormat format) : out_(out), format_(format) {}

namespace {
// JSON string escaping appended in place (the trace's hot path: no temporaries).
void append_json(std::string& r, std::string_view s) {
  r += '"';
  bool plain = true;
  for (char c : s) plain &= c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20;
  if (plain) {
    r.append(s.data(), s.size());
    r += '"';
    return;
  }
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      r += '\\';
      r += c;
    } else if (u < 0x20) {
      r += c == '\n' ? std::string("\\n") : c == '\t' ? std::string("\\t") : fmt::format("\\u{:04x}", u);
    } else {
      r += c;
    }
  }
  r += '"';
}
void append_int(std::string& r, std::int64_t v) {
  char b[24];
  auto res = std::to_chars(b, b + sizeof b, v);
  r.append(b, res.ptr);
}
}  // namespace

std::string json_string(std::string_view s) {
  std::string r = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      r += '\\';
      r += c;
    } else if (c == '\n') {
      r += "\\n";
    } else if (c == '\t') {
      r += "\\t";
    } else if (u < 0x20) {
      r += fmt::format("\\u{:04x}", u);
    } else {
      r += c;
    }
  }
  return r + "\"";
}

// Times to microseconds, trailing zeros dropped: 0.4, not 0.39999999999999997.
std::string format_time(double t) {
  std::string s = fmt::format("{:.6f}", t);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

namespace {
const char* kind_name(Event::Kind k) {
  switch (k) {
    case Event::Kind::create: return "create";
    case Event::Kind::enter: return "enter";
    case Event::Kind::arc: return "arc";
    case Event::Kind::wait: return "wait";
    case Event::Kind::resume: return "resume";
    case Event::Kind::monitor: return "monitor";
    case Event::Kind::print: return "print";
    case Event::Kind::exit: return "exit";
    case Event::Kind::kill: return "kill";
    case Event::Kind::error: return "error";
    case Event::Kind::deadlock: return "deadlock";
  }
  return "?";
}
}  // namespace

void TraceWriter::event(const Event& e) {
  ++events_;
  if (format_ == TraceFormat::none) return;
  if (format_ == TraceFormat::raw) {
    if (e.kind == Event::Kind::print) {
      buf_ += e.text;
      buf_ += '\n';
    }
  } else if (format_ == TraceFormat::json) {
    if (e.cycle != time_cycle_ || time_str_.empty()) {
      time_cycle_ = e.cycle;
      time_str_ = format_time(e.t);
    }
    buf_ += "{\"cycle\":";
    append_int(buf_, e.cycle);
    buf_ += ",\"t\":";
    buf_ += time_str_;
    if (e.inst != nullptr) {
      // ,"net":"label","var":"name" once per instance (again if its variable changes)
      const auto id = static_cast<std::size_t>(e.inst->id);
      if (prefix_.size() <= id) prefix_.resize(id + 1);
      auto& [pre, var_len] = prefix_[id];
      if (pre.empty() || var_len != e.inst->var.size()) {
        pre = ",\"net\":";
        append_json(pre, e.inst->label);
        if (!e.inst->var.empty()) {
          pre += ",\"var\":";
          append_json(pre, e.inst->var);
        }
        var_len = e.inst->var.size();
      }
      buf_ += pre;
    }
    buf_ += ",\"ev\":\"";
    buf_ += kind_name(e.kind);
    buf_ += '"';
    auto out = std::back_inserter(buf_);
    switch (e.kind) {
      case Event::Kind::create:
        buf_ += ",\"class\":" + json_string(e.cls) + ",\"args\":[";
        for (std::size_t i = 0; i < e.args.size(); ++i) buf_ += (i ? "," : "") + json_string(e.args[i]);
        buf_ += "]";
        break;
      case Event::Kind::enter:
        buf_ += ",\"node\":";
        append_json(buf_, e.node);
        break;
      case Event::Kind::arc:
        buf_ += ",\"from\":";
        append_json(buf_, e.from);
        if (e.prob >= 0) {
          fmt::format_to(out, ",\"prob\":{}", e.prob);
        } else {
          buf_ += ",\"cond\":";
          append_json(buf_, e.cond);
        }
        buf_ += ",\"to\":";
        append_json(buf_, e.to);
        break;
      case Event::Kind::wait:
        buf_ += ",\"waits\":[";
        for (std::size_t i = 0; i < e.waits.size(); ++i) buf_ += (i ? "," : "") + json_string(e.waits[i]);
        buf_ += "]";
        break;
      case Event::Kind::monitor: buf_ += ",\"name\":" + json_string(e.name); break;
      case Event::Kind::print: buf_ += ",\"text\":" + json_string(e.text); break;
      case Event::Kind::exit:
      case Event::Kind::kill:
        buf_ += ",\"status\":" + json_string(e.text);
        if (e.by != nullptr) buf_ += ",\"by\":" + json_string(e.by->label);
        if (!e.args.empty()) {
          buf_ += ",\"locals\":{";
          for (std::size_t i = 0; i < e.args.size(); ++i) {
            const std::size_t eq = e.args[i].find('=');
            buf_ += (i ? "," : "") + json_string(e.args[i].substr(0, eq)) + ":" + json_string(e.args[i].substr(eq + 1));
          }
          buf_ += "}";
        }
        break;
      case Event::Kind::error: buf_ += ",\"message\":" + json_string(e.text); break;
      case Event::Kind::resume:
      case Event::Kind::deadlock: break;
    }
    buf_ += "}\n";
  } else {
    if (events_ == 1) buf_ += "cycle\tt\tnet\tevent\tdetail\n";
    auto clean = [](std::string& s) -> const std::string& {
      for (char& c : s)
        if (c == '\t' || c == '\n') c = ' ';
      return s;
    };
    detail_.clear();
    std::string& detail = detail_;
    switch (e.kind) {
      case Event::Kind::create:
        detail = "class=" + std::string(e.cls);
        for (const auto& a : e.args) detail += " " + a;
        break;
      case Event::Kind::enter: detail.assign(e.node.data(), e.node.size()); break;
      case Event::Kind::arc:
        detail = std::string(e.from) + " " + (e.prob >= 0 ? fmt::format("{}", e.prob) : std::string(e.cond)) + " " + std::string(e.to);
        break;
      case Event::Kind::wait:
        for (std::size_t i = 0; i < e.waits.size(); ++i) detail += (i ? " " : "") + std::string(e.waits[i]);
        break;
      case Event::Kind::monitor: detail = std::string(e.name); break;
      case Event::Kind::print:
      case Event::Kind::error: detail = e.text; break;
      case Event::Kind::exit:
      case Event::Kind::kill:
        detail = e.text;
        if (e.by != nullptr) detail += " by=" + e.by->label;
        for (const auto& a : e.args) detail += " " + a;
        break;
      default: break;
    }
    if (e.cycle != time_cycle_ || time_str_.empty()) {
      time_cycle_ = e.cycle;
      time_str_ = format_time(e.t);
    }
    append_int(buf_, e.cycle);
    buf_ += '\t';
    buf_ += time_str_;
    buf_ += '\t';
    buf_ += e.inst != nullptr ? e.inst->label : std::string("-");
    buf_ += '\t';
    buf_ += kind_name(e.kind);
    buf_ += '\t';
    buf_ += clean(detail);
    buf_ += '\n';
  }
  if (!hold_ && buf_.size() > (1u << 16)) flush();
}

void TraceWriter::flush() {
  if (hold_ || buf_.empty()) return;
  if (std::fwrite(buf_.data(), 1, buf_.size(), out_) != buf_.size()) throw io_error("cannot write the trace to standard output");
  buf_.clear();
}

}  // namespace fest::patnet_tool

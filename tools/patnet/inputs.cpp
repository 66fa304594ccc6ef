#include "inputs.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "core/text_lines.hpp"
#include "formats/table/table_io.hpp"

namespace fest::patnet_tool {

using patnet::InputEvent;
using patnet::Value;

namespace {

Value to_value(const nlohmann::json& j, patnet::Machine& m, const std::string& where) {
  if (j.is_null()) return Value::nil();
  if (j.is_boolean()) return Value::boolean(j.get<bool>());
  if (j.is_number_integer()) return Value::integer(j.get<std::int64_t>());
  if (j.is_number()) return Value::real(j.get<double>());
  if (j.is_string()) return Value::string(j.get<std::string>());
  if (j.is_array()) {
    Value l;
    for (auto it = j.rbegin(); it != j.rend(); ++it) l = Value::cons(to_value(*it, m, where), l);
    return l;
  }
  throw bad_input("JSON objects cannot be PaT-Lisp values ({})", where);
}

}  // namespace

std::vector<InputEvent> parse_events(const std::string& bytes, const std::string& name, patnet::Machine& m) {
  std::vector<InputEvent> out;
  double last_t = -std::numeric_limits<double>::infinity();
  for_each_nonblank_line(bytes, [&](int line, const std::string& text) {
    const std::string where = fmt::format("{}:{}", name, line);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      throw bad_input("malformed JSON: {} ({})", json_failure_words(e.what(), e.byte, text), where);
    } catch (const nlohmann::json::exception& e) {  // out_of_range: a number beyond double's range (fuzz_patnet_inputs)
      throw bad_input("malformed JSON: {} ({})", json_failure_words(e.what(), 0, text), where);
    }
    if (!j.is_object() || !j.contains("t") || !j["t"].is_number())
      throw bad_input("an event is an object with a numeric \"t\" ({})", where);
    InputEvent ev;
    ev.t = j["t"].get<double>();
    ev.where = where;
    if (!std::isfinite(ev.t)) throw bad_input("event time is not finite ({})", where);
    if (ev.t < last_t) throw bad_input("event times must not decrease ({} after {}) ({})", ev.t, last_t, where);
    last_t = ev.t;
    int kinds = 0;
    try {
      if (j.contains("set")) {
        ++kinds;
        if (!j["set"].is_object()) throw bad_input("\"set\" must be an object ({})", where);
        ev.kind = InputEvent::Kind::set;
        for (auto& [k, v] : j["set"].items()) ev.set.emplace_back(k, to_value(v, m, where));
      }
      if (j.contains("motion")) {
        ++kinds;
        const auto& mo = j["motion"];
        ev.kind = InputEvent::Kind::motion;
        ev.name = mo.at("name").get<std::string>();
        ev.start = mo.value("start", ev.t);
        ev.end = mo.at("end").get<double>();
        if (!std::isfinite(ev.start) || !std::isfinite(ev.end) || ev.end < ev.start)
          throw bad_input("a motion needs finite start <= end ({})", where);
      }
      if (j.contains("motion-done")) {
        ++kinds;
        ev.kind = InputEvent::Kind::motion_done;
        ev.name = j["motion-done"].get<std::string>();
      }
      if (j.contains("spawn")) {
        ++kinds;
        const auto& s = j["spawn"];
        if (!s.is_array() || s.empty() || !s[0].is_string())
          throw bad_input("\"spawn\" is [class, args...] ({})", where);
        ev.kind = InputEvent::Kind::spawn;
        ev.name = s[0].get<std::string>();
        for (std::size_t i = 1; i < s.size(); ++i) ev.args.push_back(to_value(s[i], m, where));
      }
      if (j.contains("eval")) {
        ++kinds;
        ev.kind = InputEvent::Kind::eval;
        ev.name = j["eval"].get<std::string>();
      }
    } catch (const nlohmann::json::exception& e) {
      throw bad_input("malformed event: {} ({})", json_failure_words(e.what(), 0, {}), where);
    }
    if (kinds != 1)
      throw bad_input("an event has exactly one of set, motion, motion-done, spawn, eval ({})", where);
    out.push_back(std::move(ev));
  });
  return out;
}

patnet::TableInput parse_table(const std::string& bytes, const std::string& name, const std::string& var) {
  Table t;
  try {
    t = formats::read_table(bytes, formats::Format::tsv);
  } catch (const Error& e) {
    throw Error(e.status(), fmt::format("{} ({})", e.what(), name));
  }
  patnet::TableInput in;
  in.var = var;
  in.names = t.names;
  in.t_col = t.find("t");
  if (in.t_col == Table::npos) throw bad_input("the table has no 't' column ({})", name);
  in.rows.assign(t.rows(), std::vector<double>(t.cols()));
  for (std::size_t r = 0; r < t.rows(); ++r) {
    for (std::size_t c = 0; c < t.cols(); ++c) in.rows[r][c] = t.columns[c][r];
    if (!std::isfinite(in.rows[r][in.t_col]) || (r > 0 && in.rows[r][in.t_col] < in.rows[r - 1][in.t_col]))
      throw bad_input("table times must be finite and not decrease (row {}) ({})", r + 1, name);
  }
  return in;
}

}  // namespace fest::patnet_tool

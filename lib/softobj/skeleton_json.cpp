#include "softobj/skeleton_json.hpp"
#include "core/quote.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace fest::softobj {

namespace {

using json = nlohmann::json;

double number(const json& j, const std::string& where) {
  if (!j.is_number()) throw bad_input("skeleton JSON: {} is not a number", where);
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw bad_input("skeleton JSON: {} is not finite", where);
  return v;
}

int index(const json& j, const std::string& where) {
  if (!j.is_number_integer()) throw bad_input("skeleton JSON: {} is not an integer index", where);
  const auto v = j.get<long long>();
  if (v < 0 || v > 1000000000) throw bad_input("skeleton JSON: {} = {} is out of range", where, v);
  return static_cast<int>(v);
}

const json& array_of(const json& doc, const char* key, std::size_t inner) {
  static const json empty = json::array();
  if (!doc.contains(key)) return empty;
  const json& a = doc[key];
  if (!a.is_array()) throw bad_input("skeleton JSON: \"{}\" is not an array", key);
  if (inner)
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!a[i].is_array() || a[i].size() != inner)
        throw bad_input("skeleton JSON: {}[{}] is not an array of {} numbers", key, i, inner);
  return a;
}

}  // namespace

Skeleton decode_skeleton(std::string_view text) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw bad_input("skeleton JSON: {}", json_failure_words(e.what(), e.byte, text));
  } catch (const json::exception& e) {  // a number beyond double's range: out_of_range, not parse_error
    throw bad_input("skeleton JSON: {}", json_failure_words(e.what(), 0, text));
  }
  if (!doc.is_object()) throw bad_input("skeleton JSON: the document is not an object");
  Skeleton s;
  const json& V = array_of(doc, "vertices", 3);
  for (std::size_t i = 0; i < V.size(); ++i) {
    const std::string w = "vertices[" + std::to_string(i) + "]";
    s.vertices.emplace_back(number(V[i][0], w), number(V[i][1], w), number(V[i][2], w));
  }
  const json& T = array_of(doc, "triangles", 3);
  for (std::size_t i = 0; i < T.size(); ++i) {
    const std::string w = "triangles[" + std::to_string(i) + "]";
    s.triangles.push_back({index(T[i][0], w), index(T[i][1], w), index(T[i][2], w)});
  }
  const json& S = array_of(doc, "segments", 2);
  for (std::size_t i = 0; i < S.size(); ++i) {
    const std::string w = "segments[" + std::to_string(i) + "]";
    s.segments.push_back({index(S[i][0], w), index(S[i][1], w)});
  }
  const json& Pt = array_of(doc, "points", 0);
  for (std::size_t i = 0; i < Pt.size(); ++i) s.points.push_back(index(Pt[i], "points[" + std::to_string(i) + "]"));
  if (doc.contains("charge")) {
    const json& c = doc["charge"];
    if (c.is_array()) {
      for (std::size_t i = 0; i < c.size(); ++i) s.charges.push_back(number(c[i], "charge[" + std::to_string(i) + "]"));
    } else {
      s.charge = number(c, "charge");
    }
  }
  if (doc.contains("iso")) s.iso = number(doc["iso"], "iso");
  if (doc.contains("units")) {
    if (!doc["units"].is_string()) throw bad_input("skeleton JSON: \"units\" is not a string");
    s.units = doc["units"].get<std::string>();
  }
  static const char* known[] = {"vertices", "triangles", "segments", "points", "charge", "iso", "units"};
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) throw bad_input("skeleton JSON: unknown member \"{}\"", it.key());
  }
  validate(s);
  return s;
}

// One vertex or triangle per line: readable and diffable.
std::string encode_skeleton(const Skeleton& s) {
  std::string out = "{\n \"vertices\": [";
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    out += (i ? ",\n  " : "\n  ") + json({s.vertices[i].x(), s.vertices[i].y(), s.vertices[i].z()}).dump();
  out += "\n ],\n \"triangles\": [";
  for (std::size_t i = 0; i < s.triangles.size(); ++i) out += (i ? ", " : "") + json(s.triangles[i]).dump();
  out += "]";
  if (!s.segments.empty()) out += ",\n \"segments\": " + json(s.segments).dump();
  if (!s.points.empty()) out += ",\n \"points\": " + json(s.points).dump();
  out += ",\n \"charge\": " + (s.charges.empty() ? json(s.charge).dump() : json(s.charges).dump());
  if (s.iso > 0) out += ",\n \"iso\": " + json(s.iso).dump();
  if (!s.units.empty()) out += ",\n \"units\": " + json(s.units).dump();
  return out + "\n}\n";
}

}  // namespace fest::softobj

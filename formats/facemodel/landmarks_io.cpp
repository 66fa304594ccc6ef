#include "formats/facemodel/landmarks_io.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/field_lines.hpp"

namespace fest::formats {

namespace {

using Line = FieldLine;

bool parse_double(const std::string& s, double& out) {
  errno = 0;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == '\0';
}

bool parse_index(const std::string& s, std::uint32_t& out) {
  if (s.empty() || s.size() > 10) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (v > 0xffffffffull) return false;
  out = static_cast<std::uint32_t>(v);
  return true;
}

double finite_number(const std::string& s, const char* what, const std::string& source, std::size_t line) {
  double v;
  if (!parse_double(s, v)) throw bad_input("{} '{}' is not a number ({}:{})", what, s, source, line);
  if (!std::isfinite(v)) throw bad_input("{} is {}, not a finite number ({}:{})", what, s, source, line);
  return v;
}

std::vector<face::LandmarkEntry> read_pts(const std::vector<Line>& lines, const std::string& source, double origin) {
  std::vector<face::LandmarkEntry> out;
  std::size_t i = 0, declared = 0;
  bool have_n = false;
  for (; i < lines.size() && lines[i].fields[0] != "{"; ++i) {
    const auto& f = lines[i].fields;
    if (f[0] == "n_points:" && f.size() == 2) {
      std::uint32_t n;
      if (!parse_index(f[1], n)) throw bad_input("pts: bad n_points '{}' ({}:{})", f[1], source, lines[i].number);
      declared = n;
      have_n = true;
    }
  }
  if (!have_n || i == lines.size()) throw bad_input("pts: expected 'n_points: N' and '{{' ({})", source);
  for (++i; i < lines.size() && lines[i].fields[0] != "}"; ++i) {
    const auto& f = lines[i].fields;
    if (f.size() != 2) throw bad_input("pts: expected 'x y' ({}:{})", source, lines[i].number);
    face::LandmarkEntry e;
    e.id = std::to_string(out.size() + 1);
    e.u = finite_number(f[0], "x", source, lines[i].number) - origin;
    e.v = finite_number(f[1], "y", source, lines[i].number) - origin;
    e.line = lines[i].number;
    out.push_back(e);
  }
  if (i == lines.size()) throw bad_input("pts: missing closing '}}' ({})", source);
  if (out.size() != declared) throw bad_input("pts: n_points is {} but {} points follow ({})", declared, out.size(), source);
  return out;
}

}  // namespace

std::vector<face::LandmarkEntry> read_landmarks(std::string_view text, const std::string& source, double pts_origin) {
  const auto lines = field_lines(text, true);
  if (lines.empty()) throw bad_input("landmark file is empty ({})", source);
  if (lines[0].fields[0] == "version:" || lines[0].fields[0] == "n_points:") return read_pts(lines, source, pts_origin);
  const auto& head = lines[0].fields;
  const bool by_vertex = head[0] == "vertex";
  if ((head[0] != "id" && !by_vertex) || head.size() < 3 || head[1] != "u" || head[2] != "v" ||
      (head.size() == 4 && head[3] != "sigma") || head.size() > 4)
    throw bad_input("landmark TSV needs a header line 'id u v [sigma]' or 'vertex u v [sigma]' ({}:{})", source, lines[0].number);
  const bool with_sigma = head.size() == 4;
  std::vector<face::LandmarkEntry> out;
  std::set<std::string> seen;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto& f = lines[i].fields;
    const std::size_t ln = lines[i].number;
    if (f.size() != head.size()) throw bad_input("expected {} columns, found {} ({}:{})", head.size(), f.size(), source, ln);
    face::LandmarkEntry e;
    e.line = ln;
    e.by_vertex = by_vertex;
    if (by_vertex) {
      if (!parse_index(f[0], e.vertex)) throw bad_input("vertex '{}' is not a non-negative integer ({}:{})", f[0], source, ln);
    } else {
      e.id = f[0];
    }
    if (!seen.insert(f[0]).second) throw bad_input("landmark '{}' appears twice ({}:{})", f[0], source, ln);
    e.u = finite_number(f[1], "u", source, ln);
    e.v = finite_number(f[2], "v", source, ln);
    if (with_sigma) {
      e.sigma = finite_number(f[3], "sigma", source, ln);
      if (!(e.sigma > 0)) throw bad_input("sigma must be positive ({}:{})", source, ln);
    }
    out.push_back(e);
  }
  return out;
}

std::vector<face::NamedVertex> read_vertex_set(std::string_view text, const std::string& source) {
  std::vector<face::NamedVertex> out;
  const auto lines = field_lines(text, true);
  // eos TOML subset: only the [landmark_mappings] section counts.
  bool toml = false;
  for (const auto& l : lines)
    if (l.fields[0].size() > 1 && l.fields[0].front() == '[') toml = true;
  std::string section;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto& f = lines[i].fields;
    const std::size_t ln = lines[i].number;
    if (toml) {
      if (f[0].front() == '[') {
        section = f[0];
        continue;
      }
      if (section != "[landmark_mappings]") continue;
      if (f.size() != 3 || f[1] != "=") throw bad_input("landmark map: expected 'name = vertex' ({}:{})", source, ln);
    } else if (f.size() != 2) {
      throw bad_input("landmark map: expected 'name<TAB>vertex' ({}:{})", source, ln);
    }
    std::string name = f[0];
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
    std::uint32_t vertex;
    if (!parse_index(f.back(), vertex)) {
      if (i == 0 && !toml) continue;  // a header line such as "name vertex"
      throw bad_input("landmark map: vertex '{}' is not a non-negative integer ({}:{})", f.back(), source, ln);
    }
    if (!seen.insert(name).second) throw bad_input("landmark map: '{}' appears twice ({}:{})", name, source, ln);
    out.push_back({name, vertex});
  }
  if (out.empty()) throw bad_input("landmark map has no entries ({})", source);
  return out;
}

face::LandmarkMap read_landmark_map(std::string_view text, const std::string& source) {
  face::LandmarkMap map;
  for (const auto& nv : read_vertex_set(text, source)) map[nv.name] = nv.vertex;
  return map;
}

std::string write_landmarks(const std::vector<face::LandmarkEntry>& entries) {
  bool sigma = false;
  bool by_vertex = !entries.empty() && entries.front().by_vertex;
  for (const auto& e : entries) sigma = sigma || e.sigma > 0;
  std::string out = by_vertex ? "vertex\tu\tv" : "id\tu\tv";
  out += sigma ? "\tsigma\n" : "\n";
  for (const auto& e : entries) {
    out += by_vertex ? std::to_string(e.vertex) : e.id;
    out += fmt::format("\t{:.9g}\t{:.9g}", e.u, e.v);
    if (sigma) out += fmt::format("\t{:.9g}", e.sigma);
    out += '\n';
  }
  return out;
}

std::string write_vertex_set(const std::vector<face::NamedVertex>& set) {
  std::string out = "name\tvertex\n";
  for (const auto& nv : set) out += nv.name + "\t" + std::to_string(nv.vertex) + "\n";
  return out;
}

}  // namespace fest::formats

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "ffd/lattice_codec.hpp"

namespace fest::ffd {

namespace {

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

// Python configparser's subset PyGeM writes: [sections], "key: value" or "key = value",
// indented continuation lines, # and ; comments. Section names and keys are lower-cased.
std::map<std::string, std::string> read_ini(std::string_view text) {
  std::map<std::string, std::string> out;
  std::string section, last_key;
  std::size_t line_no = 0, pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view raw = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#' || line[0] == ';') {
      if (line.empty()) last_key.clear();
      if (end == text.size()) break;
      continue;
    }
    if (line.front() == '[') {
      if (line.back() != ']') throw bad_input("PyGeM .prm line {}: unterminated section header", line_no);
      section = trim(std::string_view(line).substr(1, line.size() - 2));
      for (char& ch : section) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      last_key.clear();
    } else if ((raw[0] == ' ' || raw[0] == '\t') && !last_key.empty()) {
      out[last_key] += "\n" + line;
    } else {
      const std::size_t c = line.find_first_of(":=");
      if (c == std::string::npos) throw bad_input("PyGeM .prm line {}: expected 'key: value'", line_no);
      std::string key = trim(std::string_view(line).substr(0, c));
      for (char& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      last_key = section + "/" + key;
      out[last_key] = trim(std::string_view(line).substr(c + 1));
    }
    if (end == text.size()) break;
  }
  return out;
}

double number(const std::map<std::string, std::string>& ini, const std::string& key, double fallback, bool required) {
  const auto it = ini.find(key);
  if (it == ini.end()) {
    if (required) throw bad_input("PyGeM .prm: missing '{}'", key);
    return fallback;
  }
  try {
    std::size_t used = 0;
    const double v = std::stod(it->second, &used);
    if (trim(std::string_view(it->second).substr(used)).empty() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw bad_input("PyGeM .prm: '{}' is not a number ('{}')", key, it->second);
}

Eigen::Matrix3d rot(int axis, double deg) {
  const double a = deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m(i, i) = c; m(i, j) = -s; m(j, i) = s; m(j, j) = c;
  return m;
}

}  // namespace

Lattice decode_pygem_prm(std::string_view text) {
  const auto ini = read_ini(text);
  Lattice l;
  const char* xyz[3] = {"x", "y", "z"};
  Eigen::Vector3d length, angle;
  for (int a = 0; a < 3; ++a) {
    const double n = number(ini, fmt::format("box info/n control points {}", xyz[a]), 2, true);
    if (n != std::floor(n) || n < 2 || n > max_axis_points)
      throw bad_input("PyGeM .prm: n control points {} = {} is outside 2..{}", xyz[a], n, max_axis_points);
    l.dims[static_cast<std::size_t>(a)] = static_cast<int>(n);
    length[a] = number(ini, fmt::format("box info/box length {}", xyz[a]), 1, true);
    l.origin[a] = number(ini, fmt::format("box info/box origin {}", xyz[a]), 0, true);
    angle[a] = number(ini, fmt::format("box info/rotation angle {}", xyz[a]), 0, false);
  }
  // angles2matrix(z, y, x) composes reduce(dot, [Rz, Ry, Rx][::-1]) = Rx Ry Rz.
  const Eigen::Matrix3d R = rot(0, angle[0]) * rot(1, angle[1]) * rot(2, angle[2]);
  for (int a = 0; a < 3; ++a) l.axes[static_cast<std::size_t>(a)] = length[a] * R.col(a);
  l.basis.fill(Basis::bernstein);
  l.displacement.assign(l.size(), Eigen::Vector3d::Zero());
  for (int a = 0; a < 3; ++a) {
    const auto it = ini.find(fmt::format("parameters weights/parameter {}", xyz[a]));
    if (it == ini.end()) continue;
    std::istringstream lines(it->second);
    std::string row;
    while (std::getline(lines, row)) {
      if (trim(row).empty()) continue;
      std::istringstream in(row);
      long long i, j, k;
      double mu;
      std::string extra;
      if (!(in >> i >> j >> k >> mu) || (in >> extra))
        throw bad_input("PyGeM .prm: parameter {} row '{}' is not 'i j k mu'", xyz[a], trim(row));
      if (i < 0 || i >= l.dims[0] || j < 0 || j >= l.dims[1] || k < 0 || k >= l.dims[2])
        throw bad_input("PyGeM .prm: parameter {} row '{}' indexes outside the lattice", xyz[a], trim(row));
      if (!std::isfinite(mu)) throw bad_input("PyGeM .prm: parameter {} row '{}' is not finite", xyz[a], trim(row));
      l.displacement[l.index(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k))] +=
          mu * l.axes[static_cast<std::size_t>(a)];
    }
  }
  l.validate();
  return l;
}

std::string encode_pygem_prm(const Lattice& l) {
  l.validate();
  for (const Basis b : l.basis)
    if (b != Basis::bernstein) throw bad_input("PyGeM .prm holds Bernstein lattices only (basis {})", basis_name(b));
  Eigen::Matrix3d R;
  Eigen::Vector3d length;
  for (int a = 0; a < 3; ++a) {
    length[a] = l.axes[static_cast<std::size_t>(a)].norm();
    R.col(a) = l.axes[static_cast<std::size_t>(a)] / length[a];
  }
  if (!(R.transpose() * R).isIdentity(1e-12) || R.determinant() < 0)
    throw bad_input("PyGeM .prm holds boxes with orthogonal right-handed axes only");
  // Invert R = Rx(x) Ry(y) Rz(z): R(0,2) = sin y, R(1,2) = -sin x cos y, R(2,2) = cos x cos y,
  // R(0,1) = -cos y sin z, R(0,0) = cos y cos z.
  const double ay = std::asin(std::clamp(R(0, 2), -1.0, 1.0));
  const double ax = std::atan2(-R(1, 2), R(2, 2));
  const double az = std::atan2(-R(0, 1), R(0, 0));
  std::string out = "[Box info]\n";
  const char* xyz[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) out += fmt::format("n control points {}: {}\n", xyz[a], l.dims[static_cast<std::size_t>(a)]);
  for (int a = 0; a < 3; ++a) out += fmt::format("box length {}: {}\n", xyz[a], length[a]);
  for (int a = 0; a < 3; ++a) out += fmt::format("box origin {}: {}\n", xyz[a], l.origin[a]);
  const double ang[3] = {ax * 180 / M_PI, ay * 180 / M_PI, az * 180 / M_PI};
  for (int a = 0; a < 3; ++a) out += fmt::format("rotation angle {}: {}\n", xyz[a], ang[a]);
  out += "\n[Parameters weights]\n";
  for (int a = 0; a < 3; ++a) {
    out += fmt::format("parameter {}:", xyz[a]);
    bool first = true;
    for (int i = 0; i < l.dims[0]; ++i)
      for (int j = 0; j < l.dims[1]; ++j)
        for (int k = 0; k < l.dims[2]; ++k) {
          const Eigen::Vector3d d = l.displacement.empty() ? Eigen::Vector3d::Zero() : l.displacement[l.index(i, j, k)];
          const double mu = R.col(a).dot(d) / length[a];
          out += fmt::format("{}{} {} {} {}\n", first ? " " : "             ", i, j, k, mu);
          first = false;
        }
  }
  return out;
}

}  // namespace fest::ffd

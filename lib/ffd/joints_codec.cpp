#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "ffd/lattice_codec.hpp"

namespace fest::ffd {

std::vector<Joint> decode_joints(std::string_view text) {
  std::vector<Joint> out;
  std::istringstream in{std::string(text)};
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream row(line);
    Joint j;
    if (!(row >> j.name)) continue;
    if (out.empty() && j.name == "name") continue;  // header
    double v[6];
    for (double& x : v)
      if (!(row >> x)) throw bad_input("joints line {}: expected 'name x y z tx ty tz'", line_no);
    std::string extra;
    if (row >> extra) throw bad_input("joints line {}: more than 7 fields", line_no);
    for (const double x : v)
      if (!std::isfinite(x)) throw bad_input("joints line {}: non-finite number", line_no);
    j.rest = Eigen::Vector3d(v[0], v[1], v[2]);
    j.target = Eigen::Vector3d(v[3], v[4], v[5]);
    out.push_back(j);
  }
  return out;
}

}  // namespace fest::ffd

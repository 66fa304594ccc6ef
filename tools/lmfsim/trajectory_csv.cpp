#include "trajectory_csv.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::lmfsim_tool {

void append_row(std::string& out, const TrajectoryRow& r) {
  fmt::format_to(std::back_inserter(out), "{},{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
                 r.frame, r.t, r.body, r.p.x(), r.p.y(), r.p.z(), r.q.w(), r.q.x(), r.q.y(), r.q.z(), r.v.x(), r.v.y(),
                 r.v.z(), r.w.x(), r.w.y(), r.w.z());
}

std::vector<TrajectoryRow> parse_trajectory(const std::string& bytes, const std::string& name) {
  std::vector<TrajectoryRow> rows;
  std::istringstream in(bytes);
  std::string line;
  long lineno = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line + "\n" != trajectory_header())
        throw fest::bad_input("not an lmfsim trajectory CSV: header '{}' ({}:{})", fest::quoted_bytes(line, 60), name, lineno);
      header = true;
      continue;
    }
    std::vector<std::string> f;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      f.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (f.size() != 16) throw fest::bad_input("expected 16 fields, got {} ({}:{})", f.size(), name, lineno);
    double v[16];
    for (int i = 0; i < 16; ++i) {
      if (i == 2) continue;
      char* end = nullptr;
      const std::string& text = f[static_cast<std::size_t>(i)];
      v[i] = std::strtod(text.c_str(), &end);
      // The whole field, not up to an embedded NUL byte.
      if (end == text.c_str() || end != text.c_str() + text.size())
        throw fest::bad_input("field {} is not a number ({}:{})", i + 1, name, lineno);
    }
    // A frame number outside long's range (or NaN) would make the cast undefined.
    if (!(v[0] >= 0 && v[0] <= 1e15) || v[0] != std::floor(v[0]))
      throw fest::bad_input("frame {} is not a whole number in [0, 1e15] ({}:{})", fest::quoted_bytes(f[0]), name, lineno);
    TrajectoryRow r;
    r.frame = static_cast<long>(v[0]);
    r.t = v[1];
    r.body = f[2];
    r.p = {v[3], v[4], v[5]};
    r.q = fest::lmfsim::Quat(v[6], v[7], v[8], v[9]);
    r.v = {v[10], v[11], v[12]};
    r.w = {v[13], v[14], v[15]};
    rows.push_back(std::move(r));
  }
  if (!header) throw fest::bad_input("empty trajectory ({})", name);
  return rows;
}

}  // namespace fest::lmfsim_tool

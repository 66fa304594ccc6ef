// lmfsim diff: position and angle differences between two trajectories (JSON).
#include <cmath>
#include <map>
#include <set>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "trajectory_csv.hpp"

namespace fest::lmfsim_tool {

int cmd_diff(const DiffOptions& opt) {
  const auto A = parse_trajectory(fest::read_input(opt.a), opt.a);
  const auto B = parse_trajectory(fest::read_input(opt.b), opt.b);
  std::map<std::pair<long, std::string>, const TrajectoryRow*> bmap;
  for (const auto& r : B) bmap[{r.frame, r.body}] = &r;
  const std::set<std::string> only(opt.bodies.begin(), opt.bodies.end());
  double max_pos = 0, max_ang = 0, sum_pos2 = 0, sum_ang2 = 0, worst_t = 0;
  double at_pos = -1, at_ang = -1, at_t = 0;
  long n = 0;
  // Frame nearest to --at (in A's times).
  long at_frame = -1;
  if (opt.at) {
    double best = 1e300;
    for (const auto& r : A)
      if (std::abs(r.t - *opt.at) < best) best = std::abs(r.t - *opt.at), at_frame = r.frame, at_t = r.t;
  }
  for (const auto& r : A) {
    if (!only.empty() && !only.count(r.body)) continue;
    auto it = bmap.find({r.frame, r.body});
    if (it == bmap.end()) continue;
    const TrajectoryRow& s = *it->second;
    if (std::abs(s.t - r.t) > 1e-9 * std::max(1.0, std::abs(r.t)))
      throw fest::bad_input("frame {} has time {} in {} but {} in {}", r.frame, r.t, opt.a, s.t, opt.b);
    const double dp = (r.p - s.p).norm();
    const double ang = 2 * std::acos(std::min(1.0, std::abs(r.q.normalized().dot(s.q.normalized()))));
    if (dp > max_pos) max_pos = dp, worst_t = r.t;
    max_ang = std::max(max_ang, ang);
    sum_pos2 += dp * dp;
    sum_ang2 += ang * ang;
    ++n;
    if (r.frame == at_frame) at_pos = std::max(at_pos, dp), at_ang = std::max(at_ang, ang);
  }
  if (n == 0) throw fest::bad_input("the trajectories share no (frame, body) rows");
  nlohmann::json rep = {{"rows", n},
                        {"max_pos", max_pos},
                        {"rms_pos", std::sqrt(sum_pos2 / static_cast<double>(n))},
                        {"max_angle", max_ang},
                        {"rms_angle", std::sqrt(sum_ang2 / static_cast<double>(n))},
                        {"t_of_max_pos", worst_t}};
  if (opt.at) {
    if (at_pos < 0) throw fest::bad_input("no common rows at t={}", *opt.at);
    rep["at"] = {{"t", at_t}, {"max_pos", at_pos}, {"max_angle", at_ang}};
  }
  fest::write_output("-", fest::formats::write_json(rep));
  return 0;
}

}  // namespace fest::lmfsim_tool

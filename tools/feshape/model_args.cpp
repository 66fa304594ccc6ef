#include "model_args.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace fest::feshape_tool {

void parse_grid(const std::string& grid, int& rings, int& meridians) {
  char x = 0, extra = 0;
  if (std::sscanf(grid.c_str(), "%d%c%d%c", &rings, &x, &meridians, &extra) != 3 || (x != 'x' && x != 'X'))
    throw usage_error("--grid {}: expected MxN (rings x meridians), e.g. 8x8", grid);
  if (rings < 3 || meridians < 3 || rings > 1000 || meridians > 1000)
    throw usage_error("--grid {}: rings and meridians must be in 3..1000", grid);
}

feshape::Model model_from_args(const ModelArgs& a) {
  feshape::GlobalParams qs{1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0};
  if (!a.qs.empty()) {
    if (a.qs.size() != feshape::n_global) throw usage_error("--qs needs 11 values a,a1,a2,a3,e1,e2,t1,t2,b1,b2,b3, got {}", a.qs.size());
    for (int i = 0; i < feshape::n_global; ++i) qs[i] = a.qs[i];
    if (const std::string why = feshape::check_global(qs); !why.empty()) throw usage_error("--qs: {}", why);
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  if (!a.center.empty()) {
    if (a.center.size() != 3) throw usage_error("--center needs x,y,z");
    c = Eigen::Vector3d(a.center[0], a.center[1], a.center[2]);
    if (!c.allFinite()) throw usage_error("--center must be finite");
  }
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  if (!a.quat.empty()) {
    if (a.quat.size() != 4) throw usage_error("--quat needs w,x,y,z");
    q = Eigen::Quaterniond(a.quat[0], a.quat[1], a.quat[2], a.quat[3]);
    if (!q.coeffs().allFinite() || !(q.norm() > 1e-12)) throw usage_error("--quat must be a finite non-zero quaternion");
  }
  return feshape::make_model(a.rings, a.meridians, qs, c, q);
}

}  // namespace fest::feshape_tool

#include "softobj/tongue.hpp"

#include <cmath>

namespace fest::softobj {

const std::array<const char*, TongueParams::count>& TongueParams::names() {
  static const std::array<const char*, count> n = {"x0", "y0", "z0", "l1", "l2", "l3", "l4", "l5", "l6",
                                                   "l7", "l8", "l9", "a1", "a2", "a3", "c1", "c2", "c3",
                                                   "c4", "c5", "c6"} ;
  return n;
}

int TongueParams::index_of(const std::string& name) {
  for (int i = 0; i < count; ++i)
    if (name == names()[static_cast<std::size_t>(i)]) return i;
  return -1;
}

TongueParams neutral_tongue() {
  TongueParams p;
  const double v[TongueParams::count] = {0, 0, 0, 15, 18, 17, 14, 14, 20, 20, 16, 16, 15, 186, -30, 10, 10, 10, 10, 10, 10};
  for (int i = 0; i < TongueParams::count; ++i) p[i] = v[i];
  return p;
}

std::array<Eigen::Vector3d, 10> tongue_points(const TongueParams& p) {
  const double d = M_PI / 180;
  auto l = [&](int i) { return p[2 + i]; };        // l1 .. l9
  auto a = [&](int i) { return p[11 + i] * d; };   // a1 .. a3
  auto c = [&](int i) { return p[14 + i] * d; };   // c1 .. c6
  std::array<Eigen::Vector3d, 10> vl;
  vl[0] = {p[0], p[1], p[2]};
  // Median chain (App. D §4.2): alternating signs as printed.
  vl[1] = vl[0] + l(1) * Eigen::Vector3d(std::sin(a(1)), -std::cos(a(1)), 0);
  vl[2] = vl[1] + l(2) * Eigen::Vector3d(-std::sin(a(2)), std::cos(a(2)), 0);
  vl[3] = vl[2] + l(3) * Eigen::Vector3d(std::sin(a(3)), -std::cos(a(3)), 0);
  // Lateral points, left (-z) and right (+z) of each median point.
  for (int row = 0; row < 3; ++row) {
    const Eigen::Vector3d& m = vl[static_cast<std::size_t>(row + 1)];
    const int li = 4 + 2 * row, ci = 1 + 2 * row;
    vl[static_cast<std::size_t>(li)] = m + l(li) * Eigen::Vector3d(std::sin(c(ci)), 0, -std::cos(c(ci)));
    vl[static_cast<std::size_t>(li + 1)] = m + l(li + 1) * Eigen::Vector3d(std::sin(c(ci + 1)), 0, std::cos(c(ci + 1)));
  }
  return vl;
}

Skeleton tongue_skeleton(const TongueParams& p, TongueLayout layout, double rho) {
  Skeleton s;
  for (const auto& v : tongue_points(p)) s.vertices.push_back(v);
  s.triangles = {{0, 4, 1}, {0, 1, 5}, {4, 1, 6}, {1, 2, 6}, {1, 5, 7},
                 {1, 7, 2}, {6, 2, 8}, {2, 3, 8}, {2, 7, 9}, {2, 9, 3}};
  if (layout == TongueLayout::paper9) s.triangles.erase(s.triangles.begin() + 1);
  s.charge = 1;
  s.iso = 1 / rho;
  s.units = "mm";
  return s;
}

}  // namespace fest::softobj

#pragma once
// The 3-D tongue skeleton of seed App. D §4.1-4.2 (docs/softobj.md §4): ten points
// vl0..vl3 on the median (sagittal) plane and six lateral points, from the origin, nine
// lengths l1..l9, median angles a1..a3 and lateral angles c1..c6 (degrees).
// Axes: x up, y anterior (the tip vl0 is front-most, the chain runs towards -y), z lateral.

#include <array>
#include <string>
#include <vector>

#include "softobj/skeleton.hpp"

namespace fest::softobj {

// x0 y0 z0 l1..l9 a1..a3 c1..c6 (21 numbers), in this order (the TSV column order).
struct TongueParams {
  static constexpr int count = 21;
  std::array<double, count> v{};
  static const std::array<const char*, count>& names();
  // -1 when unknown.
  static int index_of(const std::string& name);
  double& operator[](int i) { return v[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
};

// The illustrative neutral shape (mm, degrees): l1=15 l2=18 l3=17, l4=l5=14, l6=l7=20,
// l8=l9=16, a = (15, 186, -30), c1..c6 = 10.
TongueParams neutral_tongue();

enum class TongueLayout { default10, paper9 };

// The ten points by the formulas of App. D §4.2 (docs/softobj.md §4.1).
std::array<Eigen::Vector3d, 10> tongue_points(const TongueParams& p);

// Points plus the triangle list of the layout: default10 is a symmetric disk of 10
// triangles (chi = 1), paper9 drops (0,1,5) for the seed's count of 9.
Skeleton tongue_skeleton(const TongueParams& p, TongueLayout layout, double rho);

}  // namespace fest::softobj

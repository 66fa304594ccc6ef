#include "isosurface/triangulate_loop.hpp"

#include <cmath>
#include <limits>

namespace fest::isosurface {
namespace {

double area2(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return std::sqrt(x * x + y * y + z * z);
}

}  // namespace

bool triangulate_loop(const std::uint32_t* ids_in, const std::array<double, 3>* pts_in, const std::uint8_t* faces_in, int n,
                      Triangulation how, std::vector<std::array<std::uint32_t, 3>>& out) {
  constexpr int kMax = 64;
  if (n > kMax) return false;  // the caller fans it around a centroid
  int start = 0;
  for (int k = 1; k < n; ++k)
    if (ids_in[k] < ids_in[start]) start = k;
  std::uint32_t id[kMax];
  std::uint8_t face[kMax];
  for (int k = 0; k < n; ++k) {
    id[k] = ids_in[(start + k) % n];
    face[k] = faces_in ? faces_in[(start + k) % n] : 0;
  }
  if (n == 3) {
    out.push_back({id[0], id[1], id[2]});
    return true;
  }
  if (how == Triangulation::centroid) return false;
  // A chord (i, j), j - i >= 2, that is not the closing loop edge (0, n-1).
  auto forbidden = [&](int i, int j) { return j - i >= 2 && !(i == 0 && j == n - 1) && (face[i] & face[j]); };
  if (how == Triangulation::fan) {
    bool ok = true;
    for (int k = 2; k + 1 < n; ++k) ok = ok && !forbidden(0, k);
    if (ok) {
      for (int k = 1; k + 1 < n; ++k) out.push_back({id[0], id[k], id[k + 1]});
      return true;
    }
  }
  const std::array<double, 3>* p[kMax];
  for (int k = 0; k < n; ++k) p[k] = &pts_in[(start + k) % n];
  // Dynamic programme over the polygon's triangulations (O(n^3)): best[i][j] is the least
  // area of triangulating the sub-polygon i..j; split[i][j] the apex chosen.
  double best[kMax][kMax];
  int split[kMax][kMax];
  for (int gap = 1; gap < n; ++gap)
    for (int i = 0; i + gap < n; ++i) {
      const int j = i + gap;
      if (gap == 1) {
        best[i][j] = 0;
        continue;
      }
      best[i][j] = std::numeric_limits<double>::infinity();
      if (forbidden(i, j)) continue;
      for (int m = i + 1; m < j; ++m) {
        const double c = best[i][m] + best[m][j] + area2(*p[i], *p[m], *p[j]);
        if (c < best[i][j]) {
          best[i][j] = c;
          split[i][j] = m;
        }
      }
    }
  if (!(best[0][n - 1] < std::numeric_limits<double>::infinity())) return false;
  // Emit in a fixed order (depth first, apex before the sub-polygons).
  int stack[2 * kMax][2];
  int top = 0;
  stack[top][0] = 0;
  stack[top++][1] = n - 1;
  while (top > 0) {
    --top;
    const int i = stack[top][0], j = stack[top][1];
    if (j - i < 2) continue;
    const int m = split[i][j];
    out.push_back({id[i], id[m], id[j]});
    stack[top][0] = m;
    stack[top++][1] = j;
    stack[top][0] = i;
    stack[top++][1] = m;
  }
  return true;
}

}  // namespace fest::isosurface

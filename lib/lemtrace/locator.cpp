#include "lemtrace/locator.hpp"

#include <algorithm>
#include <cmath>

namespace fest::lemtrace {

Eigen::Vector4d barycentric(const TetMesh& mesh, int32_t cell, const Vec3& x) {
  const Tet& t = mesh.tets[static_cast<std::size_t>(cell)];
  const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
  const Vec3 e1 = mesh.points[static_cast<std::size_t>(t[1])] - a;
  const Vec3 e2 = mesh.points[static_cast<std::size_t>(t[2])] - a;
  const Vec3 e3 = mesh.points[static_cast<std::size_t>(t[3])] - a;
  const Vec3 r1 = e2.cross(e3);
  const double inv = 1.0 / e1.dot(r1);
  const Vec3 d = x - a;
  const double b1 = d.dot(r1) * inv, b2 = d.dot(e3.cross(e1)) * inv, b3 = d.dot(e1.cross(e2)) * inv;
  return {1.0 - b1 - b2 - b3, b1, b2, b3};
}

CellLocator::CellLocator(const TetMesh& mesh) : mesh_(mesh) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (mesh.tets.empty()) return;
  const Vec3 size = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  // About two cells per bin, with bins shaped like the domain.
  const double per_bin = std::cbrt(size.prod() * 2.0 / static_cast<double>(mesh.tets.size()));
  for (int a = 0; a < 3; ++a) n_[a] = std::clamp(static_cast<int>(size[a] / per_bin), 1, 1024);
  lo_ = lo;
  for (int a = 0; a < 3; ++a) inv_size_[a] = n_[a] / size[a];
  const std::size_t n_bins = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  start_.assign(n_bins + 1, 0);
  auto range = [&](const Tet& t, int lo_i[3], int hi_i[3]) {
    Vec3 a = mesh.points[static_cast<std::size_t>(t[0])], b = a;
    for (int k = 1; k < 4; ++k) {
      a = a.cwiseMin(mesh.points[static_cast<std::size_t>(t[k])]);
      b = b.cwiseMax(mesh.points[static_cast<std::size_t>(t[k])]);
    }
    for (int d = 0; d < 3; ++d) {
      lo_i[d] = std::clamp(static_cast<int>((a[d] - lo_[d]) * inv_size_[d]), 0, n_[d] - 1);
      hi_i[d] = std::clamp(static_cast<int>((b[d] - lo_[d]) * inv_size_[d]), 0, n_[d] - 1);
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<uint32_t> fill;
    if (pass == 1) {
      for (std::size_t i = 0; i < n_bins; ++i) start_[i + 1] += start_[i];
      cells_.resize(start_[n_bins]);
      fill.assign(start_.begin(), start_.end() - 1);
    }
    for (std::size_t c = 0; c < mesh.tets.size(); ++c) {
      int l[3], h[3];
      range(mesh.tets[c], l, h);
      for (int k = l[2]; k <= h[2]; ++k)
        for (int j = l[1]; j <= h[1]; ++j)
          for (int i = l[0]; i <= h[0]; ++i) {
            if (pass == 0) ++start_[bin(i, j, k) + 1];
            else cells_[fill[bin(i, j, k)]++] = static_cast<int32_t>(c);
          }
    }
  }
}

int32_t CellLocator::locate(const Vec3& x) const {
  if (cells_.empty() || !x.allFinite()) return -1;
  int idx[3];
  for (int d = 0; d < 3; ++d) {
    const double f = (x[d] - lo_[d]) * inv_size_[d];
    if (f < -1e-9 * n_[d] || f > n_[d] * (1 + 1e-9)) return -1;
    idx[d] = std::clamp(static_cast<int>(f), 0, n_[d] - 1);
  }
  const std::size_t b = bin(idx[0], idx[1], idx[2]);
  int32_t best = -1;
  double best_min = -1e-12;
  for (uint32_t i = start_[b]; i < start_[b + 1]; ++i) {
    const double m = barycentric(mesh_, cells_[i], x).minCoeff();
    if (m >= 0) return cells_[i];
    if (m >= best_min) {
      best_min = m;
      best = cells_[i];
    }
  }
  return best;
}

int32_t CellLocator::walk(int32_t start, const Vec3& x, int64_t* calls, Eigen::Vector4d* beta) const {
  int32_t cell = start;
  for (int step = 0; step < 64 && cell >= 0; ++step) {
    if (calls) ++*calls;
    const Eigen::Vector4d b = barycentric(mesh_, cell, x);
    int k;
    const double m = b.minCoeff(&k);
    if (m >= -1e-12) {
      if (beta) *beta = b;
      return cell;
    }
    const int32_t next = mesh_.neighbors[static_cast<std::size_t>(cell)][k];
    if (next < 0) break;
    cell = next;
  }
  if (calls) ++*calls;
  const int32_t found = locate(x);
  if (beta && found >= 0) *beta = barycentric(mesh_, found, x);
  return found;
}

}  // namespace fest::lemtrace

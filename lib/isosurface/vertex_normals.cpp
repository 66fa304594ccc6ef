// Vertex normals from the interpolated central-difference gradient: docs/isosurf.md
// "Vertex normals".
#include "isosurface/vertex_normals.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel_for.hpp"

namespace fest::isosurface {
namespace {

using volume_pyramid::ScalarGrid;

// Central difference along axis a at sample q (one-sided at the border).
double central(const ScalarGrid& g, const std::size_t q[3], int a) {
  std::size_t lo[3] = {q[0], q[1], q[2]}, hi[3] = {q[0], q[1], q[2]};
  if (lo[a] > 0) --lo[a];
  if (hi[a] + 1 < g.dims[a]) ++hi[a];
  return (double(g.at(hi[0], hi[1], hi[2])) - g.at(lo[0], lo[1], lo[2])) / double(hi[a] - lo[a]);
}

}  // namespace

void add_gradient_normals(const ScalarGrid& g, Surface& s, int threads) {
  const std::size_t nv = s.vertices();
  s.normals.assign(3 * nv, 0.0f);
  if (nv == 0 || g.dims[0] < 2 || g.dims[1] < 2 || g.dims[2] < 2) return;
  // index = A^-1 (world - origin); gradients map to world space by A^-T
  const auto& A = g.axes;
  const double det = g.determinant();
  const double inv[9] = {(A[4] * A[8] - A[5] * A[7]) / det, (A[2] * A[7] - A[1] * A[8]) / det, (A[1] * A[5] - A[2] * A[4]) / det,
                         (A[5] * A[6] - A[3] * A[8]) / det, (A[0] * A[8] - A[2] * A[6]) / det, (A[2] * A[3] - A[0] * A[5]) / det,
                         (A[3] * A[7] - A[4] * A[6]) / det, (A[1] * A[6] - A[0] * A[7]) / det, (A[0] * A[4] - A[1] * A[3]) / det};
  // fallback: area-weighted triangle normals (oriented outwards by the extractor)
  std::vector<double> face(3 * nv, 0.0);
  for (const auto& t : s.triangles) {
    const float* a = &s.xyz[3 * t[0]];
    const float* b = &s.xyz[3 * t[1]];
    const float* c = &s.xyz[3 * t[2]];
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (auto vi : t)
      for (int k = 0; k < 3; ++k) face[3 * vi + k] += n[k];
  }
  parallel_for((nv + 4095) / 4096, threads, [&](std::size_t chunk) {
    for (std::size_t v = chunk * 4096; v < std::min(nv, (chunk + 1) * 4096); ++v) {
      const double d[3] = {s.xyz[3 * v] - g.origin[0], s.xyz[3 * v + 1] - g.origin[1], s.xyz[3 * v + 2] - g.origin[2]};
      std::size_t c[3];
      double w[3];
      for (int a = 0; a < 3; ++a) {
        const double x = std::clamp(inv[3 * a] * d[0] + inv[3 * a + 1] * d[1] + inv[3 * a + 2] * d[2], 0.0, double(g.dims[a] - 1));
        c[a] = std::min(static_cast<std::size_t>(x), g.dims[a] - 2);
        w[a] = x - double(c[a]);
      }
      double gi[3] = {0, 0, 0};
      for (int corner = 0; corner < 8; ++corner) {
        const std::size_t q[3] = {c[0] + (corner & 1), c[1] + (corner >> 1 & 1), c[2] + (corner >> 2 & 1)};
        const double wt = (corner & 1 ? w[0] : 1 - w[0]) * (corner >> 1 & 1 ? w[1] : 1 - w[1]) * (corner >> 2 & 1 ? w[2] : 1 - w[2]);
        for (int a = 0; a < 3; ++a) gi[a] += wt * central(g, q, a);
      }
      // world gradient = A^-T grad_index; the normal points down the gradient (outwards)
      double n[3];
      for (int a = 0; a < 3; ++a) n[a] = -(inv[a] * gi[0] + inv[3 + a] * gi[1] + inv[6 + a] * gi[2]);
      double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(len > 0) || !std::isfinite(len)) {
        for (int a = 0; a < 3; ++a) n[a] = face[3 * v + a];
        len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      }
      if (len > 0)
        for (int a = 0; a < 3; ++a) s.normals[3 * v + a] = static_cast<float>(n[a] / len);
    }
  });
}

}  // namespace fest::isosurface

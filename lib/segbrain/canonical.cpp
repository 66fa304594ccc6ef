// Axis permutation/flip from the direction cosines.
#include "segbrain/canonical.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::segbrain {

Reorientation find_reorientation(const Volume& v) {
  Reorientation r;
  const char* pos = "RAS";
  const char* neg = "LPI";
  std::array<bool, 3> used{false, false, false};
  r.code = "???";
  for (int c = 0; c < 3; ++c) {
    // Column c of the direction matrix: the world direction of voxel axis c.
    int best = -1;
    double bestv = -1;
    for (int w = 0; w < 3; ++w) {
      double x = std::fabs(v.direction[3 * w + c]);
      if (!used[w] && x > bestv) {
        bestv = x;
        best = w;
      }
    }
    used[best] = true;
    bool negative = v.direction[3 * best + c] < 0;
    r.source_axis[best] = c;
    r.flip[best] = negative;
    r.code[c] = negative ? neg[best] : pos[best];
    r.obliquity_deg = std::max(r.obliquity_deg, std::acos(std::min(1.0, bestv)) * 180.0 / M_PI);
  }
  return r;
}

Grid canonical_grid(const Volume& v, const Reorientation& r) {
  Grid g;
  for (int a = 0; a < 3; ++a) {
    g.n[a] = v.dims[r.source_axis[a]];
    g.spacing[a] = v.spacing[r.source_axis[a]];
  }
  return g;
}

namespace {

// Source voxel index of canonical voxel (i0, i1, i2).
template <typename F>
void for_each_voxel(const Volume& v, const Reorientation& r, const Grid& g, F&& f) {
  std::array<std::size_t, 3> src{};
  for (std::size_t k = 0; k < g.n[2]; ++k)
    for (std::size_t j = 0; j < g.n[1]; ++j)
      for (std::size_t i = 0; i < g.n[0]; ++i) {
        std::array<std::size_t, 3> c{i, j, k};
        for (int a = 0; a < 3; ++a) src[r.source_axis[a]] = r.flip[a] ? g.n[a] - 1 - c[a] : c[a];
        f(g.index(i, j, k), v.index(src[0], src[1], src[2]));
      }
}

}  // namespace

Image to_canonical(const Volume& v, const Reorientation& r) {
  Grid g = canonical_grid(v, r);
  Image out(g.size());
  for_each_voxel(v, r, g, [&](std::size_t ci, std::size_t si) { out[ci] = static_cast<float>(v.voxels[si]); });
  return out;
}

std::vector<double> from_canonical(const std::vector<double>& canon, const Volume& v, const Reorientation& r) {
  Grid g = canonical_grid(v, r);
  std::vector<double> out(v.size());
  for_each_voxel(v, r, g, [&](std::size_t ci, std::size_t si) { out[si] = canon[ci]; });
  return out;
}

}  // namespace fest::segbrain

// Lateral extent by rows (docs/segbrain.md §5, "The brainstem"): where a row meets CSF the
// side ends there; where it runs on (a peduncle, the diencephalon) the side is the chord
// between the closed sides above and below it, as an anatomist draws the pons against the
// middle cerebellar peduncle from the cistern's notch to the ventricle's edge.
#include "segbrain/lateral_extent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fest::segbrain {

namespace {

constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();
constexpr double kOpen = -1.0;

bool present(double v) { return !std::isnan(v); }
bool is_open_end(double v) { return v == kOpen; }

// Fills the open entries of one line of ends (`count` entries `stride` apart from `first`)
// by linear interpolation between the nearest closed entries on both sides.
void interpolate_line(std::vector<double>& ends, std::size_t first, std::size_t stride, std::size_t count) {
  std::size_t prev = count;  // index of the last closed entry, count = none
  for (std::size_t k = 0; k < count; ++k) {
    const double v = ends[first + k * stride];
    if (!present(v) || is_open_end(v)) continue;
    if (prev != count)
      for (std::size_t m = prev + 1; m < k; ++m) {
        double& e = ends[first + m * stride];
        if (!is_open_end(e)) continue;
        const double a = ends[first + prev * stride];
        e = a + (v - a) * double(m - prev) / double(k - prev);
      }
    prev = k;
  }
}

double median_of(std::vector<double>& v) {
  const std::size_t h = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h), v.end());
  if (v.size() % 2) return v[h];
  const double upper = v[h];
  return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h)));
}

}  // namespace

Mask lateral_extent(const Grid& g, const Mask& candidate, const Mask& within, double plane_r_mm, double max_half_width_mm,
                    LateralExtentStats* stats) {
  const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
  const double sx = g.spacing[0];
  LateralExtentStats st;
  // ends[side][y + ny * z]: distance (mm) from the plane to the centre of the side's last
  // voxel; NaN where the row has no candidate voxel on that side, kOpen where it is open.
  std::vector<double> ends[2] = {std::vector<double>(ny * nz, kAbsent), std::vector<double>(ny * nz, kAbsent)};
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y) {
      const std::size_t row = g.index(0, y, z);
      // Innermost candidate voxel on each side of the plane.
      long inner[2] = {-1, -1};
      for (std::size_t x = 0; x < nx; ++x) {
        if (!candidate[row + x]) continue;
        const double p = double(x) * sx;
        if (p <= plane_r_mm) inner[0] = long(x);
        if (p >= plane_r_mm && inner[1] < 0) inner[1] = long(x);
      }
      for (int side = 0; side < 2; ++side) {
        if (inner[side] < 0) continue;
        ++st.sides;
        const long step = side == 0 ? -1 : 1;
        long x = inner[side];
        auto dist = [&](long xi) { return std::fabs(double(xi) * sx - plane_r_mm); };
        bool is_open = dist(x) > max_half_width_mm;
        while (!is_open) {
          const long nxt = x + step;
          if (nxt < 0 || nxt >= long(nx) || !within[row + std::size_t(nxt)]) break;  // the boundary
          if (dist(nxt) > max_half_width_mm) {
            is_open = true;
            break;
          }
          x = nxt;
        }
        if (is_open) ++st.open_sides;
        ends[side][y + ny * z] = is_open ? kOpen : dist(x);
      }
    }

  for (auto& e : ends) {
    for (std::size_t y = 0; y < ny; ++y) interpolate_line(e, y, ny, nz);  // along S: the chord in the coronal section
    for (std::size_t z = 0; z < nz; ++z) interpolate_line(e, ny * z, 1, ny);  // along A, in the axial section
    for (std::size_t z = 0; z < nz; ++z) {
      std::vector<double> closed;
      for (std::size_t y = 0; y < ny; ++y)
        if (present(e[y + ny * z]) && !is_open_end(e[y + ny * z])) closed.push_back(e[y + ny * z]);
      const double fill = closed.empty() ? max_half_width_mm : median_of(closed);
      for (std::size_t y = 0; y < ny; ++y)
        if (is_open_end(e[y + ny * z])) e[y + ny * z] = fill;
    }
    // Median over the rows within 2 mm along S and 1 mm along A: one row's stray end (a
    // vessel, a sulcus of partial volume) does not notch the outline.
    const long hy = long(std::floor(1.0 / g.spacing[1] + 1e-9)), hz = long(std::floor(2.0 / g.spacing[2] + 1e-9));
    std::vector<double> smooth(e.size(), kAbsent), window;
    for (long z = 0; z < long(nz); ++z)
      for (long y = 0; y < long(ny); ++y) {
        if (!present(e[std::size_t(y) + ny * std::size_t(z)])) continue;
        window.clear();
        for (long dz = -hz; dz <= hz; ++dz)
          for (long dy = -hy; dy <= hy; ++dy) {
            const long yy = y + dy, zz = z + dz;
            if (yy < 0 || zz < 0 || yy >= long(ny) || zz >= long(nz)) continue;
            const double v = e[std::size_t(yy) + ny * std::size_t(zz)];
            if (present(v)) window.push_back(v);
          }
        smooth[std::size_t(y) + ny * std::size_t(z)] = median_of(window);
      }
    e.swap(smooth);
  }

  Mask out(g.size(), 0);
  constexpr double eps = 1e-6;
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y) {
      const double l = ends[0][y + ny * z], r = ends[1][y + ny * z];
      if (!present(l) && !present(r)) continue;
      const std::size_t row = g.index(0, y, z);
      for (std::size_t x = 0; x < nx; ++x) {
        const double p = double(x) * sx;
        if ((present(l) && p <= plane_r_mm && plane_r_mm - p <= l + eps) || (present(r) && p >= plane_r_mm && p - plane_r_mm <= r + eps))
          out[row + x] = 1;
      }
    }
  if (stats) *stats = st;
  return out;
}

}  // namespace fest::segbrain

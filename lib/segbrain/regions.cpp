// Region division by edges, the starting region and slice-wise aggregation.
#include "segbrain/regions.hpp"

#include <algorithm>
#include <deque>

namespace fest::segbrain {

Regions divide_into_regions(const Grid& g, const Mask& edges, const Mask& within, const Image& img, const Mask& skin_zone,
                            bool per_slice) {
  Regions r;
  r.label.assign(g.size(), 0);
  r.table.emplace_back();
  std::vector<double> sum(1, 0), sx(1, 0), sy(1, 0);
  std::vector<std::size_t> stack;
  const long nx = long(g.n[0]), ny = long(g.n[1]), nz = long(g.n[2]);
  for (std::size_t seed = 0; seed < g.size(); ++seed) {
    if (!within[seed] || edges[seed] || r.label[seed]) continue;
    const auto id = static_cast<std::uint32_t>(r.table.size());
    Region reg;
    reg.slice = seed / (g.n[0] * g.n[1]);
    double s = 0, ax = 0, ay = 0;
    r.label[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      const long x = long(i % g.n[0]), y = long((i / g.n[0]) % g.n[1]), z = long(i / (g.n[0] * g.n[1]));
      ++reg.voxels;
      s += img[i];
      ax += double(x);
      ay += double(y);
      reg.skin_contact = reg.skin_contact || (!skin_zone.empty() && skin_zone[i]);
      const long nb[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
      for (int k = 0; k < (per_slice ? 4 : 6); ++k) {
        const long X = x + nb[k][0], Y = y + nb[k][1], Z = z + nb[k][2];
        if (X < 0 || Y < 0 || Z < 0 || X >= nx || Y >= ny || Z >= nz) continue;
        const std::size_t j = g.index(std::size_t(X), std::size_t(Y), std::size_t(Z));
        if (within[j] && !edges[j] && !r.label[j]) {
          r.label[j] = id;
          stack.push_back(j);
        }
      }
    }
    reg.mean = s / double(reg.voxels);
    reg.cx = ax / double(reg.voxels);
    reg.cy = ay / double(reg.voxels);
    r.table.push_back(reg);
  }
  // Adjacency through edge voxels.
  r.adjacent.assign(r.table.size(), {});
  std::vector<std::uint32_t> seen;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!edges[i]) continue;
    const long x = long(i % g.n[0]), y = long((i / g.n[0]) % g.n[1]), z = long(i / (g.n[0] * g.n[1]));
    seen.clear();
    for (long dz = per_slice ? 0 : -1; dz <= (per_slice ? 0 : 1); ++dz)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dx = -1; dx <= 1; ++dx) {
          const long X = x + dx, Y = y + dy, Z = z + dz;
          if (X < 0 || Y < 0 || Z < 0 || X >= nx || Y >= ny || Z >= nz) continue;
          const std::uint32_t l = r.label[g.index(std::size_t(X), std::size_t(Y), std::size_t(Z))];
          if (l && std::find(seen.begin(), seen.end(), l) == seen.end()) seen.push_back(l);
        }
    for (auto a : seen)
      for (auto b : seen)
        if (a != b) r.adjacent[a].push_back(b);
  }
  for (auto& v : r.adjacent) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return r;
}

std::uint32_t brain_starting_region(const Grid& g, const Regions& r, const Mask& head, double lo, double hi,
                                    double ref_fraction) {
  std::size_t z0 = g.n[2], z1 = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    if (head[i]) {
      const std::size_t z = i / (g.n[0] * g.n[1]);
      z0 = std::min(z0, z);
      z1 = std::max(z1, z);
    }
  if (z0 > z1) return 0;
  const auto zr = static_cast<std::size_t>(double(z0) + ref_fraction * double(z1 - z0) + 0.5);
  // The head's R and A extents in that slice.
  double x0 = 1e300, x1 = -1, y0 = 1e300, y1 = -1;
  for (std::size_t y = 0; y < g.n[1]; ++y)
    for (std::size_t x = 0; x < g.n[0]; ++x)
      if (head[g.index(x, y, zr)]) {
        x0 = std::min(x0, double(x)), x1 = std::max(x1, double(x));
        y0 = std::min(y0, double(y)), y1 = std::max(y1, double(y));
      }
  if (x1 < 0) return 0;
  std::uint32_t best = 0;
  for (std::uint32_t id = 1; id < r.table.size(); ++id) {
    const Region& q = r.table[id];
    if (q.slice != zr || q.skin_contact || q.mean < lo || q.mean > hi) continue;
    if (q.cx < x0 + 0.25 * (x1 - x0) || q.cx > x1 - 0.25 * (x1 - x0) || q.cy < y0 + 0.25 * (y1 - y0) ||
        q.cy > y1 - 0.25 * (y1 - y0))
      continue;
    if (!best || q.voxels > r.table[best].voxels) best = id;
  }
  return best;
}

Mask aggregate_brain_regions(const Grid& g, const Regions& r, std::uint32_t start, double lo, double hi,
                             double min_overlap, double min_area_mm2) {
  Mask out(g.size(), 0);
  if (!start || start >= r.table.size()) return out;
  auto qualifies = [&](std::uint32_t id) {
    const Region& q = r.table[id];
    return !q.skin_contact && q.mean >= lo && q.mean <= hi;
  };
  std::vector<std::uint8_t> accepted(r.table.size(), 0);
  // Breadth first within one slice from the given seeds.
  auto grow = [&](std::vector<std::uint32_t> seeds) {
    std::deque<std::uint32_t> queue(seeds.begin(), seeds.end());
    for (auto s : seeds) accepted[s] = 1;
    while (!queue.empty()) {
      const auto id = queue.front();
      queue.pop_front();
      for (auto nb : r.adjacent[id])
        if (!accepted[nb] && r.table[nb].slice == r.table[id].slice && qualifies(nb)) {
          accepted[nb] = 1;
          queue.push_back(nb);
        }
    }
  };
  grow({start});
  const std::size_t plane = g.n[0] * g.n[1];
  const double pixel_mm2 = g.spacing[0] * g.spacing[1];
  auto area_of = [&](std::size_t z) {
    std::size_t n = 0;
    for (std::size_t i = z * plane; i < (z + 1) * plane; ++i) n += r.label[i] && accepted[r.label[i]];
    return double(n) * pixel_mm2;
  };
  const std::size_t zr = r.table[start].slice;
  for (int dir : {1, -1}) {
    for (long z = long(zr) + dir; z >= 0 && z < long(g.n[2]); z += dir) {
      const std::size_t prev = std::size_t(z - dir);
      // Overlap of each region of slice z with the accepted part of the previous slice.
      std::vector<std::size_t> overlap(r.table.size(), 0);
      for (std::size_t k = 0; k < plane; ++k) {
        const auto here = r.label[std::size_t(z) * plane + k], below = r.label[prev * plane + k];
        if (here && below && accepted[below]) ++overlap[here];
      }
      std::vector<std::uint32_t> seeds;
      for (std::uint32_t id = 1; id < r.table.size(); ++id)
        if (overlap[id] && double(overlap[id]) >= min_overlap * double(r.table[id].voxels) && qualifies(id))
          seeds.push_back(id);
      if (seeds.empty()) break;
      grow(seeds);
      if (area_of(std::size_t(z)) < min_area_mm2) break;
    }
  }
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = r.label[i] && accepted[r.label[i]];
  // Edge voxels between accepted regions belong to the brain (they lie inside it; left
  // out they would make its contour ragged): those whose in-slice 4-neighbours in
  // regions are all accepted, at least one of them.
  Mask inner(g.size(), 0);
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 1; y + 1 < g.n[1]; ++y)
      for (std::size_t x = 1; x + 1 < g.n[0]; ++x) {
        const std::size_t i = g.index(x, y, z);
        if (r.label[i]) continue;
        int in = 0, out_of = 0;
        for (std::size_t j : {i - 1, i + 1, i - g.n[0], i + g.n[0]}) {
          if (!r.label[j]) continue;
          (accepted[r.label[j]] ? in : out_of)++;
        }
        inner[i] = in > 0 && out_of == 0;
      }
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = out[i] || inner[i];
  return out;
}

}  // namespace fest::segbrain

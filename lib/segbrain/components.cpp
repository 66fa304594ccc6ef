// Connected components on runs (docs/segbrain.md §3: O(N)), and the hole filling built on them.
//
// Each row (fixed y, z) is cut into runs of consecutive mask voxels; a run joins the runs
// of the earlier neighbouring rows that it touches (the neighbourhood decides which rows
// and whether diagonal contact counts), with union-find whose root is always the run
// earliest in raster order. Numbering the roots in run order then gives the ids a raster
// flood fill gives: id k is the component whose first voxel comes k-th in raster order.
// Runs are found and labels written slice by slice in parallel; the unions, a small
// fraction of the work, run in one fixed order, so the result never depends on threads.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "segbrain/morphology.hpp"
#include "segbrain/parallel.hpp"

namespace fest::segbrain {
namespace {

struct Run {
  std::uint32_t x0, x1;  // [x0, x1)
};

// Runs of a mask (or of its complement) in raster order, with where each row's runs start.
struct Runs {
  std::vector<Run> run;
  std::vector<std::size_t> row_start;  // size rows + 1; row = y + ny z
};

std::uint64_t load8(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}

// Index of the first byte from x on whose nonzero-ness differs from `nonzero` (nx when
// none); whole words of 8 alike bytes are skipped at once, so long runs cost little.
std::size_t skip_alike(const std::uint8_t* row, std::size_t x, std::size_t nx, bool nonzero) {
  constexpr std::uint64_t kOnes = 0x0101010101010101ull, kHighs = 0x8080808080808080ull;
  if (nonzero) {
    while (x + 8 <= nx) {
      const std::uint64_t v = load8(row + x);
      if ((v - kOnes) & ~v & kHighs) break;  // the word holds a zero byte
      x += 8;
    }
    while (x < nx && row[x] != 0) ++x;
  } else {
    while (x + 8 <= nx && load8(row + x) == 0) x += 8;
    while (x < nx && row[x] == 0) ++x;
  }
  return x;
}

Runs find_runs(const Grid& g, const Mask& m, bool complement) {
  const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
  const bool run_nonzero = !complement;  // runs of the mask, or of its complement
  std::vector<std::vector<Run>> per_slice(nz);
  std::vector<std::vector<std::uint32_t>> per_row_count(nz, std::vector<std::uint32_t>(ny));
  parallel_bands(nz, 4, [&](std::size_t, std::size_t z0, std::size_t z1) {
    for (std::size_t z = z0; z < z1; ++z)
      for (std::size_t y = 0; y < ny; ++y) {
        const std::uint8_t* row = m.data() + g.index(0, y, z);
        std::size_t x = 0;
        const std::size_t before = per_slice[z].size();
        while (x < nx) {
          x = skip_alike(row, x, nx, !run_nonzero);  // background
          if (x == nx) break;
          const std::size_t x0 = x;
          x = skip_alike(row, x, nx, run_nonzero);
          per_slice[z].push_back({static_cast<std::uint32_t>(x0), static_cast<std::uint32_t>(x)});
        }
        per_row_count[z][y] = static_cast<std::uint32_t>(per_slice[z].size() - before);
      }
  });
  Runs r;
  std::size_t total = 0;
  for (const auto& s : per_slice) total += s.size();
  r.run.reserve(total);
  // Slices in order, rows in order within each: raster order.
  r.row_start.resize(ny * nz);
  for (std::size_t z = 0; z < nz; ++z) {
    std::size_t at = r.run.size();
    for (std::size_t y = 0; y < ny; ++y) {
      r.row_start[z * ny + y] = at;
      at += per_row_count[z][y];
    }
    r.run.insert(r.run.end(), per_slice[z].begin(), per_slice[z].end());
  }
  r.row_start.push_back(r.run.size());
  return r;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a < b) parent[b] = a;
  else if (b < a) parent[a] = b;
}

// Unites the runs of row `cur` with the runs of row `prev` they touch; tol 1 lets runs
// touch diagonally (|dx| = 1), tol 0 needs a shared x.
void join_rows(const Runs& r, std::size_t cur, std::size_t prev, std::uint32_t tol, std::vector<std::uint32_t>& parent) {
  std::size_t i = r.row_start[cur], ie = r.row_start[cur + 1];
  std::size_t j = r.row_start[prev], je = r.row_start[prev + 1];
  while (i < ie && j < je) {
    const Run& a = r.run[i];
    const Run& b = r.run[j];
    if (a.x0 < b.x1 + tol && b.x0 < a.x1 + tol) unite(parent, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
    if (a.x1 < b.x1) ++i;
    else ++j;
  }
}

// Union-find parents of the runs under the given connectivity (4/8 join rows of one axial
// slice only); every parent index is <= its child's.
std::vector<std::uint32_t> link_runs(const Grid& g, const Runs& r, int conn) {
  if (r.run.size() >= std::size_t{0xffffffffu}) throw std::length_error("too many runs for 32-bit component ids");
  std::vector<std::uint32_t> parent(r.run.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<std::uint32_t>(i);
  const std::size_t ny = g.n[1], nz = g.n[2];
  const bool planar = conn == 4 || conn == 8;
  // Earlier rows (dy, dz) and whether diagonal contact along x counts there.
  struct Neighbour {
    int dy, dz;
    std::uint32_t tol;
  };
  static constexpr Neighbour k4[] = {{-1, 0, 0}}, k8[] = {{-1, 0, 1}}, k6[] = {{-1, 0, 0}, {0, -1, 0}},
                             k18[] = {{-1, 0, 1}, {0, -1, 1}, {-1, -1, 0}, {1, -1, 0}},
                             k26[] = {{-1, 0, 1}, {0, -1, 1}, {-1, -1, 1}, {1, -1, 1}};
  const Neighbour* nb = conn == 4 ? k4 : conn == 8 ? k8 : conn == 6 ? k6 : conn == 18 ? k18 : k26;
  const std::size_t nn = conn == 4 || conn == 8 ? 1 : conn == 6 ? 2 : 4;
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y) {
      const std::size_t cur = y + ny * z;
      if (r.row_start[cur] == r.row_start[cur + 1]) continue;
      for (std::size_t k = 0; k < nn; ++k) {
        const Neighbour& n = nb[k];
        const long py = static_cast<long>(y) + n.dy, pz = static_cast<long>(z) + n.dz;
        if (py < 0 || pz < 0 || py >= static_cast<long>(ny) || (planar && n.dz != 0)) continue;
        join_rows(r, cur, static_cast<std::size_t>(py) + ny * static_cast<std::size_t>(pz), n.tol, parent);
      }
    }
  return parent;
}

void check_conn(int conn) {
  if (conn != 4 && conn != 8 && conn != 6 && conn != 18 && conn != 26)
    throw std::invalid_argument("connectivity must be 4, 8, 6, 18 or 26");
}

// Component id (1..) of every run, numbered in raster order of the components' first
// voxels, and the size of every id.
struct RunLabels {
  Runs runs;
  std::vector<std::uint32_t> id;
  std::vector<std::size_t> size;  // size[0] unused
};

RunLabels label_runs(const Grid& g, const Mask& m, int conn, bool complement) {
  check_conn(conn);
  RunLabels L;
  L.runs = find_runs(g, m, complement);
  std::vector<std::uint32_t> parent = link_runs(g, L.runs, conn);
  L.id.resize(parent.size());
  L.size.assign(1, 0);
  for (std::size_t i = 0; i < parent.size(); ++i) {
    const std::uint32_t root = find_root(parent, static_cast<std::uint32_t>(i));
    if (root == i) {
      L.id[i] = static_cast<std::uint32_t>(L.size.size());
      L.size.push_back(0);
    } else {
      L.id[i] = L.id[root];  // root < i: already numbered
    }
    L.size[L.id[i]] += L.runs.run[i].x1 - L.runs.run[i].x0;
  }
  return L;
}

// Writes value(id of run) over every run into out (other voxels keep their value),
// slice-parallel.
template <typename T, typename Value>
void paint_runs(const Grid& g, const RunLabels& L, std::vector<T>& out, Value&& value) {
  const std::size_t ny = g.n[1];
  parallel_bands(g.n[2], 4, [&](std::size_t, std::size_t z0, std::size_t z1) {
    for (std::size_t z = z0; z < z1; ++z)
      for (std::size_t y = 0; y < ny; ++y) {
        T* row = out.data() + g.index(0, y, z);
        const std::size_t row_id = y + ny * z;
        for (std::size_t i = L.runs.row_start[row_id]; i < L.runs.row_start[row_id + 1]; ++i) {
          const T v = value(L.id[i]);
          std::fill(row + L.runs.run[i].x0, row + L.runs.run[i].x1, v);
        }
      }
  });
}

}  // namespace

Components connected_components(const Grid& g, const Mask& m, int conn) {
  RunLabels L = label_runs(g, m, conn, false);
  Components c;
  c.label.assign(g.size(), 0);
  paint_runs(g, L, c.label, [](std::uint32_t id) { return id; });
  c.size = std::move(L.size);
  return c;
}

Mask largest_component(const Grid& g, const Mask& m, int conn) {
  RunLabels L = label_runs(g, m, conn, false);
  Mask out(g.size(), 0);
  if (L.size.size() < 2) return out;
  // Ties go to the lower id, the component met first in raster order.
  const auto best = static_cast<std::uint32_t>(std::max_element(L.size.begin() + 1, L.size.end()) - L.size.begin());
  paint_runs(g, L, out, [best](std::uint32_t id) { return static_cast<std::uint8_t>(id == best); });
  return out;
}

Mask fill_holes(const Grid& g, const Mask& m, bool per_slice) {
  // Components of the background (4-connected per slice, or 6-connected); those with a
  // run on the grid border are the outside, the others holes.
  RunLabels L = label_runs(g, m, per_slice ? 4 : 6, true);
  std::vector<std::uint8_t> outside(L.size.size(), 0);
  const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y) {
      const std::size_t row_id = y + ny * z;
      const bool border_row = y == 0 || y + 1 == ny || (!per_slice && (z == 0 || z + 1 == nz));
      for (std::size_t i = L.runs.row_start[row_id]; i < L.runs.row_start[row_id + 1]; ++i)
        if (border_row || L.runs.run[i].x0 == 0 || L.runs.run[i].x1 == nx) outside[L.id[i]] = 1;
    }
  Mask out(g.size(), 1);
  paint_runs(g, L, out, [&](std::uint32_t id) { return static_cast<std::uint8_t>(!outside[id]); });
  return out;
}

Mask fill_holes_sections(const Grid& g, const Mask& m, int axis) {
  if (axis == 2) return fill_holes(g, m, true);
  // Relabel the axes so that `axis` becomes the third (the section index) and fill the
  // axial sections of the permuted grid; x stays first when it is not the section axis.
  const std::array<int, 3> order = axis == 1 ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{1, 2, 0};
  Grid t;
  for (int k = 0; k < 3; ++k) t.n[k] = g.n[order[k]], t.spacing[k] = g.spacing[order[k]];
  Mask tm(m.size());
  std::array<std::size_t, 3> p{};
  auto src_index = [&](const std::array<std::size_t, 3>& q) {
    std::array<std::size_t, 3> o{};
    for (int k = 0; k < 3; ++k) o[order[k]] = q[k];
    return g.index(o[0], o[1], o[2]);
  };
  for (p[2] = 0; p[2] < t.n[2]; ++p[2])
    for (p[1] = 0; p[1] < t.n[1]; ++p[1])
      for (p[0] = 0; p[0] < t.n[0]; ++p[0]) tm[t.index(p[0], p[1], p[2])] = m[src_index(p)];
  const Mask filled = fill_holes(t, tm, true);
  Mask out(m.size());
  for (p[2] = 0; p[2] < t.n[2]; ++p[2])
    for (p[1] = 0; p[1] < t.n[1]; ++p[1])
      for (p[0] = 0; p[0] < t.n[0]; ++p[0]) out[src_index(p)] = filled[t.index(p[0], p[1], p[2])];
  return out;
}

}  // namespace fest::segbrain

// Loop construction of docs/isosurf.md "Loop construction", steps 1-3, tabulated.
#include "isosurface/cell_loops.hpp"

#include <stdexcept>

namespace fest::isosurface {
namespace {

struct Geometry {
  std::array<std::array<std::uint8_t, 4>, 6> faces{};
  std::array<EdgeInfo, 12> edges{};
  std::array<std::array<int, 8>, 8> edge_of{};  // corner pair -> edge (or -1)

  Geometry() {
    for (auto& row : edge_of) row.fill(-1);
    for (int v = 0; v < 8; ++v)
      for (int axis = 0; axis < 3; ++axis) {
        if (v >> axis & 1) continue;
        const int x = v & 1, y = v >> 1 & 1, z = v >> 2 & 1;
        const int e = axis == 0 ? y + 2 * z : axis == 1 ? 4 + x + 2 * z : 8 + x + 2 * y;
        edges[e] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(axis)};
        edge_of[v][v | 1 << axis] = edge_of[v | 1 << axis][v] = e;
      }
    for (int f = 0; f < 6; ++f) {
      const int a = f / 2, s = f % 2, u = (a + 1) % 3, w = (a + 2) % 3;
      const int su[4] = {0, 1, 1, 0}, sw[4] = {0, 0, 1, 1};
      for (int q = 0; q < 4; ++q) faces[f][q] = static_cast<std::uint8_t>(s << a | su[q] << u | sw[q] << w);
    }
  }
};

const Geometry& geometry() {
  static const Geometry g;
  return g;
}

std::array<double, 3> corner_point(int v) { return {double(v & 1), double(v >> 1 & 1), double(v >> 2 & 1)}; }

std::array<double, 3> edge_mid(int e) {
  const auto& info = geometry().edges[e];
  auto p = corner_point(info.corner);
  p[info.axis] = 0.5;
  return p;
}

struct Table {
  std::array<CellLoops, 256 * 64> loops{};
  std::array<std::uint8_t, 256> ambiguous{};
  Table() {
    for (int c = 0; c < 256; ++c) {
      ambiguous[c] = 0;
      for (int f = 0; f < 6; ++f) {
        const auto& q = geometry().faces[f];
        const bool i0 = c >> q[0] & 1, i1 = c >> q[1] & 1, i2 = c >> q[2] & 1, i3 = c >> q[3] & 1;
        if (i0 == i2 && i1 == i3 && i0 != i1) ambiguous[c] |= static_cast<std::uint8_t>(1 << f);
      }
      for (int d = 0; d < 64; ++d) {
        if (d & ~ambiguous[c]) continue;  // decisions only matter on ambiguous faces
        CellLoops& out = loops[c * 64 + d];
        int at = 0;
        for (const auto& loop : build_loops(c, d)) {
          out.length[out.count++] = static_cast<std::uint8_t>(loop.size());
          for (int e : loop) out.edges[at++] = static_cast<std::uint8_t>(e);
        }
      }
    }
  }
};

const Table& table() {
  static const Table t;
  return t;
}

}  // namespace

const std::array<std::uint8_t, 4>& face_corners(int face) { return geometry().faces[face]; }
const EdgeInfo& edge_info(int edge) { return geometry().edges[edge]; }
std::uint8_t edge_faces(int edge) {
  static const std::array<std::uint8_t, 12> masks = [] {
    std::array<std::uint8_t, 12> m{};
    for (int e = 0; e < 12; ++e) {
      const auto& info = geometry().edges[e];
      for (int a = 0; a < 3; ++a)
        if (a != info.axis) m[e] |= static_cast<std::uint8_t>(1 << (2 * a + (info.corner >> a & 1)));
    }
    return m;
  }();
  return masks[edge];
}
std::uint8_t ambiguous_faces(int cube_case) { return table().ambiguous[cube_case]; }
const CellLoops& cell_loops(int cube_case, int connected) { return table().loops[cube_case * 64 + (connected & table().ambiguous[cube_case])]; }

std::vector<std::vector<int>> build_loops(int c, int connected) {
  const Geometry& g = geometry();
  std::array<int, 12> next;
  next.fill(-1);
  for (int f = 0; f < 6; ++f) {
    const auto& q = g.faces[f];
    bool in[4];
    for (int k = 0; k < 4; ++k) in[k] = c >> q[k] & 1;
    // Square edge k joins corners k and k+1.
    int sq_edge[4];
    for (int k = 0; k < 4; ++k) sq_edge[k] = g.edge_of[q[k]][q[(k + 1) % 4]];
    std::vector<std::array<int, 2>> segs;  // pairs of square edges
    const int crossed = (in[0] != in[1]) + (in[1] != in[2]) + (in[2] != in[3]) + (in[3] != in[0]);
    if (crossed == 2) {
      int a = -1, b = -1;
      for (int k = 0; k < 4; ++k)
        if (in[k] != in[(k + 1) % 4]) (a < 0 ? a : b) = k;
      segs.push_back({a, b});
    } else if (crossed == 4) {
      // Corner k is adjacent to square edges k-1 and k. Cut off the corners of the class
      // that is NOT connected across the face.
      const bool connect_inside = connected >> f & 1;
      for (int k = 0; k < 4; ++k)
        if (in[k] != connect_inside) segs.push_back({(k + 3) % 4, k});
    }
    const auto a = g.faces[f];
    const int axis = f / 2;
    double n[3] = {0, 0, 0};
    n[axis] = f % 2 ? 1.0 : -1.0;
    for (auto s : segs) {
      int ep = sq_edge[s[0]], eq = sq_edge[s[1]];
      // Orient p -> q so that n x (q - p) points away from the inside corner of p's edge.
      const auto p = edge_mid(ep), qq = edge_mid(eq);
      const int kin = in[s[0]] ? s[0] : (s[0] + 1) % 4;
      const auto ci = corner_point(a[kin]);
      const double d[3] = {qq[0] - p[0], qq[1] - p[1], qq[2] - p[2]};
      const double x[3] = {n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]};
      const double side = x[0] * (ci[0] - p[0]) + x[1] * (ci[1] - p[1]) + x[2] * (ci[2] - p[2]);
      if (side > 0) std::swap(ep, eq);
      if (next[ep] != -1) throw std::logic_error("isosurface: two segments leave one edge");
      next[ep] = eq;
    }
  }
  std::vector<std::vector<int>> loops;
  std::array<bool, 12> used{};
  for (int e = 0; e < 12; ++e) {
    if (next[e] < 0 || used[e]) continue;
    std::vector<int> loop;
    for (int x = e; !used[x]; x = next[x]) {
      if (next[x] < 0) throw std::logic_error("isosurface: open loop");
      used[x] = true;
      loop.push_back(x);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace fest::isosurface

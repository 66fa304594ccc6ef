#include "lemtrace/split_cells.hpp"

#include <algorithm>

namespace fest::lemtrace {
namespace {

using Quad = std::array<int64_t, 4>;  // cyclic order
using TetIds = std::array<int64_t, 4>;

// Two triangles of a quadrilateral, cut through its smallest vertex, each joined to apex.
void pyramid(int64_t apex, const Quad& q, std::vector<TetIds>& out) {
  int m = static_cast<int>(std::min_element(q.begin(), q.end()) - q.begin());
  int64_t a = q[m], b = q[(m + 1) % 4], c = q[(m + 2) % 4], d = q[(m + 3) % 4];
  out.push_back({apex, a, b, c});
  out.push_back({apex, a, c, d});
}

bool split_hexahedron(const int64_t* v, std::vector<TetIds>& out) {
  // VTK hexahedron: bottom 0-1-2-3, top 4-5-6-7 (4 above 0).
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  int apex = static_cast<int>(std::min_element(v, v + 8) - v);
  for (const auto& f : faces) {
    bool has_apex = f[0] == apex || f[1] == apex || f[2] == apex || f[3] == apex;
    if (!has_apex) pyramid(v[apex], {v[f[0]], v[f[1]], v[f[2]], v[f[3]]}, out);
  }
  return true;
}

bool split_wedge(const int64_t* v, std::vector<TetIds>& out) {
  // VTK wedge: triangles 0-1-2 and 3-4-5, quads 0-1-4-3, 1-2-5-4, 2-0-3-5.
  static const int quads[3][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  int apex = static_cast<int>(std::min_element(v, v + 6) - v);
  for (const auto& q : quads) {
    bool has_apex = q[0] == apex || q[1] == apex || q[2] == apex || q[3] == apex;
    if (!has_apex) pyramid(v[apex], {v[q[0]], v[q[1]], v[q[2]], v[q[3]]}, out);
  }
  // The triangle not containing the apex closes the wedge.
  if (apex < 3) {
    out.push_back({v[apex], v[3], v[4], v[5]});
  } else {
    out.push_back({v[apex], v[0], v[1], v[2]});
  }
  return true;
}

}  // namespace

bool split_cell(uint8_t vtk_type, const int64_t* ids, int64_t count, std::vector<TetIds>& out) {
  switch (vtk_type) {
    case static_cast<uint8_t>(CellShape::tetra):
      if (count != 4) return false;
      out.push_back({ids[0], ids[1], ids[2], ids[3]});
      return true;
    case static_cast<uint8_t>(CellShape::voxel): {
      if (count != 8) return false;
      // Voxel order is lexicographic (x fastest); reorder to hexahedron order.
      const int64_t hex[8] = {ids[0], ids[1], ids[3], ids[2], ids[4], ids[5], ids[7], ids[6]};
      return split_hexahedron(hex, out);
    }
    case static_cast<uint8_t>(CellShape::hexahedron):
      return count == 8 && split_hexahedron(ids, out);
    case static_cast<uint8_t>(CellShape::wedge):
      return count == 6 && split_wedge(ids, out);
    case static_cast<uint8_t>(CellShape::pyramid):
      if (count != 5) return false;
      pyramid(ids[4], {ids[0], ids[1], ids[2], ids[3]}, out);
      return true;
    default:
      return false;
  }
}

}  // namespace fest::lemtrace

#include "lemtrace/tet_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "lemtrace/split_cells.hpp"

namespace fest::lemtrace {

void RawCells::add(uint8_t type, std::initializer_list<int64_t> cell_ids) {
  if (offsets.empty()) offsets.push_back(0);
  types.push_back(type);
  ids.insert(ids.end(), cell_ids.begin(), cell_ids.end());
  offsets.push_back(static_cast<int64_t>(ids.size()));
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

namespace {

const char* vtk_cell_name(int type) {
  switch (type) {
    case 1: return "vertex";
    case 3: return "line";
    case 5: return "triangle";
    case 7: return "polygon";
    case 8: return "pixel";
    case 9: return "quad";
    case 24: return "quadratic tetrahedron";
    case 25: return "quadratic hexahedron";
    case 42: return "polyhedron";
    default: return "cell";
  }
}

// Vertex -> incident tets (CSR), for matching faces without a table of all faces.
struct Incidence {
  std::vector<int64_t> start;
  std::vector<int32_t> tets;
};

Incidence incidence(const std::vector<Tet>& tets, std::size_t n_points) {
  Incidence inc;
  inc.start.assign(n_points + 1, 0);
  for (const Tet& t : tets)
    for (int32_t v : t) ++inc.start[static_cast<std::size_t>(v) + 1];
  for (std::size_t i = 0; i < n_points; ++i) inc.start[i + 1] += inc.start[i];
  inc.tets.resize(tets.size() * 4);
  std::vector<int64_t> fill(inc.start.begin(), inc.start.end() - 1);
  for (std::size_t c = 0; c < tets.size(); ++c)
    for (int32_t v : tets[c]) inc.tets[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int32_t>(c);
  return inc;
}

bool contains(const Tet& t, int32_t v) { return t[0] == v || t[1] == v || t[2] == v || t[3] == v; }

}  // namespace

TetMesh build_tet_mesh(std::vector<Vec3> points, std::vector<Vec3> vectors, const RawCells& cells,
                       const BuildOptions& options, MeshReport* report) {
  MeshReport local;
  MeshReport& rep = report ? *report : local;
  rep = MeshReport{};
  rep.input_cells = cells.size();
  if (vectors.size() != points.size())
    throw bad_input("{} vectors for {} points", vectors.size(), points.size());
  const auto n_points = static_cast<int64_t>(points.size());
  if (n_points > INT32_MAX) throw bad_input("{} points is more than lemtrace indexes (2^31)", n_points);

  TetMesh mesh;
  std::vector<std::array<int64_t, 4>> split;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const int64_t begin = cells.offsets[c], end = cells.offsets[c + 1];
    const int type = cells.types[c];
    for (int64_t i = begin; i < end; ++i)
      if (cells.ids[static_cast<std::size_t>(i)] < 0 || cells.ids[static_cast<std::size_t>(i)] >= n_points)
        throw bad_input("cell {} refers to point {}, the grid has {} points", c, cells.ids[static_cast<std::size_t>(i)], n_points);
    if (type != static_cast<int>(CellShape::tetra)) {
      if (!options.split)
        throw bad_input("cell {} is a VTK type {} cell and, unsplit, only tetrahedra are accepted", c, type);
      ++rep.split_cells;
    }
    split.clear();
    if (!split_cell(static_cast<uint8_t>(type), cells.ids.data() + begin, end - begin, split))
      throw bad_input("cell {} is a {} (VTK type {}) with {} points; lemtrace takes tetrahedra, hexahedra, "
                      "voxels, wedges and pyramids",
                      c, vtk_cell_name(type), type, end - begin);
    for (const auto& s : split) {
      mesh.tets.push_back({static_cast<int32_t>(s[0]), static_cast<int32_t>(s[1]), static_cast<int32_t>(s[2]),
                           static_cast<int32_t>(s[3])});
      mesh.source_cell.push_back(static_cast<int64_t>(c));
    }
  }

  // Orientation and degeneracy: a zero-volume tet has no linear interpolant (E is
  // singular), so the grid cannot be traced through it.
  for (std::size_t c = 0; c < mesh.tets.size(); ++c) {
    Tet& t = mesh.tets[c];
    const Vec3 &a = points[t[0]], &b = points[t[1]], &p = points[t[2]], &d = points[t[3]];
    double h = std::max({(b - a).norm(), (p - a).norm(), (d - a).norm(), (p - b).norm(), (d - b).norm(), (d - p).norm()});
    double vol = signed_volume(a, b, p, d);
    if (!(std::abs(vol) > 1e-14 * h * h * h))
      throw bad_input("tetrahedron {} (from cell {}) has zero volume (points {} {} {} {}); lemtrace needs "
                      "non-degenerate cells",
                      c, mesh.source_cell[c], t[0], t[1], t[2], t[3]);
    if (vol < 0) {
      std::swap(t[2], t[3]);
      ++rep.flipped;
    }
  }

  // Face neighbours: the tets sharing face k of c all contain its smallest vertex.
  Incidence inc = incidence(mesh.tets, points.size());
  mesh.neighbors.assign(mesh.tets.size(), Tet{-1, -1, -1, -1});
  for (std::size_t c = 0; c < mesh.tets.size(); ++c) {
    const Tet& t = mesh.tets[c];
    for (int k = 0; k < 4; ++k) {
      if (mesh.neighbors[c][k] >= 0) continue;
      int32_t f0 = t[kFaceVertex[k][0]], f1 = t[kFaceVertex[k][1]], f2 = t[kFaceVertex[k][2]];
      int32_t lo = std::min({f0, f1, f2});
      int found = 0;
      for (int64_t i = inc.start[static_cast<std::size_t>(lo)]; i < inc.start[static_cast<std::size_t>(lo) + 1]; ++i) {
        int32_t o = inc.tets[static_cast<std::size_t>(i)];
        if (o == static_cast<int32_t>(c)) continue;
        const Tet& u = mesh.tets[static_cast<std::size_t>(o)];
        if (!contains(u, f0) || !contains(u, f1) || !contains(u, f2)) continue;
        if (++found > 1)
          throw bad_input("non-manifold mesh: the face ({}, {}, {}) belongs to more than two tetrahedra", f0, f1, f2);
        int opposite = 0;
        while (u[opposite] == f0 || u[opposite] == f1 || u[opposite] == f2) ++opposite;
        mesh.neighbors[c][k] = o;
        if (mesh.neighbors[static_cast<std::size_t>(o)][opposite] >= 0 &&
            mesh.neighbors[static_cast<std::size_t>(o)][opposite] != static_cast<int32_t>(c))
          throw bad_input("non-manifold mesh: the face ({}, {}, {}) belongs to more than two tetrahedra", f0, f1, f2);
        mesh.neighbors[static_cast<std::size_t>(o)][opposite] = static_cast<int32_t>(c);
      }
      if (found == 0) ++rep.boundary_faces;
    }
  }
  mesh.points = std::move(points);
  mesh.vectors = std::move(vectors);
  return mesh;
}

}  // namespace fest::lemtrace

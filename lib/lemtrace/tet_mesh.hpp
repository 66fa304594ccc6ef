#pragma once
// The tetrahedral mesh lemtrace traces through (chapter 9, §9.3.2: vertex list with
// positions and vectors; cell list with four vertex ids in positive orientation and the
// four face neighbours, T_k across the face opposite V_k, -1 on the boundary).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::lemtrace {

using Vec3 = Eigen::Vector3d;
using Tet = std::array<int32_t, 4>;

// Cells as VTK describes them (type codes of vtkCellType.h), before splitting.
enum class CellShape : uint8_t { tetra = 10, voxel = 11, hexahedron = 12, wedge = 13, pyramid = 14 };

struct RawCells {
  std::vector<uint8_t> types;      // VTK cell type code per cell
  std::vector<int64_t> offsets;    // size cells + 1: ids[offsets[c] .. offsets[c+1])
  std::vector<int64_t> ids;        // point ids
  void add(uint8_t type, std::initializer_list<int64_t> cell_ids);
  std::size_t size() const noexcept { return types.size(); }
};

struct TetMesh {
  std::vector<Vec3> points;
  std::vector<Vec3> vectors;        // one per point
  std::vector<Tet> tets;            // positively oriented
  std::vector<Tet> neighbors;       // neighbors[c][k]: across the face opposite vertex k
  std::vector<int64_t> source_cell; // input cell each tet came from
};

// What building the mesh changed or found (reported by the tool).
struct MeshReport {
  std::size_t input_cells = 0;
  std::size_t split_cells = 0;      // non-tetrahedral cells split into tets
  std::size_t flipped = 0;          // tets reordered to positive orientation
  std::size_t boundary_faces = 0;
};

struct BuildOptions {
  bool split = true;                // false: non-tetrahedral cells are rejected
};

// Splits, orients and connects. Throws bad_input for unsupported cell types, cells with
// ids out of range, zero-volume tetrahedra and faces shared by more than two tets.
TetMesh build_tet_mesh(std::vector<Vec3> points, std::vector<Vec3> vectors, const RawCells& cells,
                       const BuildOptions& options, MeshReport* report);

// Face k of a tet is opposite vertex k; these are its vertex positions in the tet.
constexpr int kFaceVertex[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace fest::lemtrace

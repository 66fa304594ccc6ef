#pragma once
// Conforming split of hexahedra, voxels, wedges and pyramids into tetrahedra (docs/lemtrace.md).
//
// Rule (after Dompierre et al. 1999): every quadrilateral face is cut along the
// diagonal through its vertex with the smallest global id. Two cells sharing a face see
// the same ids, so they cut it the same way and the split mesh is conforming. A hexahedron
// is cut into the three pyramids that join its smallest-id vertex to the three faces
// not containing it (each pyramid then splits along its base's diagonal): 6 tetrahedra,
// no Steiner point, and the three faces through the apex are cut through the apex, which
// is their smallest vertex too. A wedge is the pyramid from its smallest vertex to the
// opposite quadrilateral plus one tetrahedron; a pyramid splits along its base diagonal.
// On a structured grid this gives the Kuhn (Freudenthal) split of every cube.

#include <cstdint>
#include <vector>

#include "lemtrace/tet_mesh.hpp"

namespace fest::lemtrace {

// Appends the tetrahedra of one cell (VTK vertex order) to `out`. Orientation is not
// fixed here. Returns false for a cell type this split does not know.
bool split_cell(uint8_t vtk_type, const int64_t* ids, int64_t count, std::vector<std::array<int64_t, 4>>& out);

}  // namespace fest::lemtrace

#pragma once
// The tetrahedral mesh as VTK sees it: one vtkTetra per tet and the point vectors as
// "velocity". Kept apart from fest_lemtrace so that the solver stays free of VTK; the
// tool's dataset output and the vtkStreamTracer benchmark both start from this grid.

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "lemtrace/tet_mesh.hpp"

namespace fest::lemtrace {

vtkSmartPointer<vtkUnstructuredGrid> tet_mesh_to_vtk(const TetMesh& mesh);

}  // namespace fest::lemtrace

#include "lemtrace/vtk/tet_grid.hpp"

#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

namespace fest::lemtrace {

vtkSmartPointer<vtkUnstructuredGrid> tet_mesh_to_vtk(const TetMesh& mesh) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto vel = vtkSmartPointer<vtkDoubleArray>::New();
  vel->SetName("velocity");
  vel->SetNumberOfComponents(3);
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    points->InsertNextPoint(mesh.points[i].data());
    vel->InsertNextTuple(mesh.vectors[i].data());
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(vel);
  grid->Allocate(static_cast<vtkIdType>(mesh.tets.size()));
  for (const auto& t : mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  return grid;
}

}  // namespace fest::lemtrace

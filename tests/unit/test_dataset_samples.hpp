#pragma once
// Datasets built in code, with values known from their construction, and a strict
// comparison, for the dataset format tests.

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace fest::test {

// 4 x 5 x 6 grid, unit spacing, origin 0: point array f = x + 2y + 3z (so f runs
// from 0 to 3 + 2*4 + 3*5 = 26) and cell array "cell_id" = cell index.
inline vtkSmartPointer<vtkImageData> make_image() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(4, 5, 6);
  image->SetSpacing(1, 1, 1);
  image->SetOrigin(0, 0, 0);
  auto f = vtkSmartPointer<vtkDoubleArray>::New();
  f->SetName("f");
  f->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double p[3];
    image->GetPoint(i, p);
    f->SetValue(i, p[0] + 2 * p[1] + 3 * p[2]);
  }
  image->GetPointData()->SetScalars(f);
  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName("cell_id");
  ids->SetNumberOfTuples(image->GetNumberOfCells());
  for (vtkIdType i = 0; i < image->GetNumberOfCells(); ++i) ids->SetValue(i, static_cast<int>(i));
  image->GetCellData()->AddArray(ids);
  return image;
}

// The unit cube [0,1]^3 cut into six tetrahedra around its diagonal (0,0,0)-(1,1,1)
// (Kuhn's triangulation), with the solid-body rotation v = (-y, x, 0) at the points:
// |v| runs from 0 (on the z axis) to sqrt(2) (at x = y = 1).
inline vtkSmartPointer<vtkUnstructuredGrid> make_tets() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int corner = 0; corner < 8; ++corner)  // bit 0: x, bit 1: y, bit 2: z
    points->InsertNextPoint(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const int axes[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (const auto& order : axes) {
    vtkIdType tet[4] = {0, order[0], order[0] + order[1], 7};
    grid->InsertNextCell(VTK_TETRA, 4, tet);
  }
  auto velocity = vtkSmartPointer<vtkDoubleArray>::New();
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(8);
  for (vtkIdType i = 0; i < 8; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    double v[3] = {-p[1], p[0], 0.0};
    velocity->SetTuple(i, v);
  }
  grid->GetPointData()->SetVectors(velocity);
  auto region = vtkSmartPointer<vtkIntArray>::New();
  region->SetName("region");
  for (int i = 0; i < 6; ++i) region->InsertNextValue(10 + i);
  grid->GetCellData()->AddArray(region);
  return grid;
}

// A 4 x 2 sheet of points in z = 0: three quads, one triangle strip over the same
// points, a line and a vertex; point array "height" = x * y (float).
inline vtkSmartPointer<vtkPolyData> make_poly() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) points->InsertNextPoint(0.5 * i, 0.25 * j, 0.0);
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 0; i < 3; ++i) {
    vtkIdType quad[4] = {i, i + 1, i + 5, i + 4};
    quads->InsertNextCell(4, quad);
  }
  auto strips = vtkSmartPointer<vtkCellArray>::New();
  vtkIdType strip[8] = {0, 4, 1, 5, 2, 6, 3, 7};
  strips->InsertNextCell(8, strip);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  vtkIdType line[2] = {0, 3};
  lines->InsertNextCell(2, line);
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  vtkIdType vert[1] = {7};
  verts->InsertNextCell(1, vert);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(quads);
  poly->SetStrips(strips);
  poly->SetLines(lines);
  poly->SetVerts(verts);
  auto height = vtkSmartPointer<vtkFloatArray>::New();
  height->SetName("height");
  for (vtkIdType i = 0; i < 8; ++i) {
    double p[3];
    points->GetPoint(i, p);
    height->InsertNextValue(static_cast<float>(p[0] * p[1]));
  }
  poly->GetPointData()->AddArray(height);
  return poly;
}

// A 3 x 2 x 2 curvilinear grid (a sheared box) with point array "w" = i + 10 j + 100 k.
inline vtkSmartPointer<vtkStructuredGrid> make_structured_grid() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto w = vtkSmartPointer<vtkDoubleArray>::New();
  w->SetName("w");
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        points->InsertNextPoint(i + 0.5 * j, j, k + 0.25 * i);
        w->InsertNextValue(i + 10 * j + 100 * k);
      }
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(3, 2, 2);
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(w);
  return grid;
}

// A rectilinear grid with uneven spacing and a cell array "c" = cell index.
inline vtkSmartPointer<vtkRectilinearGrid> make_rectilinear_grid() {
  auto axis = [](std::vector<double> values) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    for (double v : values) a->InsertNextValue(v);
    return a;
  };
  auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
  grid->SetDimensions(4, 3, 2);
  grid->SetXCoordinates(axis({0.0, 0.1, 0.5, 2.0}));
  grid->SetYCoordinates(axis({-1.0, 0.0, 1.0}));
  grid->SetZCoordinates(axis({0.0, 3.0}));
  auto c = vtkSmartPointer<vtkIntArray>::New();
  c->SetName("c");
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) c->InsertNextValue(static_cast<int>(i));
  grid->GetCellData()->AddArray(c);
  return grid;
}

inline void expect_same_arrays(vtkDataSetAttributes* expected, vtkDataSetAttributes* actual, const char* kind) {
  ASSERT_EQ(expected->GetNumberOfArrays(), actual->GetNumberOfArrays()) << kind;
  for (int a = 0; a < expected->GetNumberOfArrays(); ++a) {
    vtkDataArray* want = expected->GetArray(a);
    ASSERT_NE(want, nullptr);
    vtkDataArray* got = actual->GetArray(want->GetName());
    ASSERT_NE(got, nullptr) << kind << " array " << want->GetName() << " is missing";
    EXPECT_EQ(want->GetDataType(), got->GetDataType()) << want->GetName();
    ASSERT_EQ(want->GetNumberOfComponents(), got->GetNumberOfComponents()) << want->GetName();
    ASSERT_EQ(want->GetNumberOfTuples(), got->GetNumberOfTuples()) << want->GetName();
    for (vtkIdType t = 0; t < want->GetNumberOfTuples(); ++t)
      for (int c = 0; c < want->GetNumberOfComponents(); ++c)
        ASSERT_EQ(want->GetComponent(t, c), got->GetComponent(t, c)) << want->GetName() << "[" << t << "," << c << "]";
  }
}

// Same points (exactly), same cells (type and point ids, in order), same arrays.
inline void expect_same_dataset(vtkDataSet* expected, vtkDataSet* actual) {
  ASSERT_NE(actual, nullptr);
  ASSERT_EQ(expected->GetNumberOfPoints(), actual->GetNumberOfPoints());
  ASSERT_EQ(expected->GetNumberOfCells(), actual->GetNumberOfCells());
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i) {
    double p[3], q[3];
    expected->GetPoint(i, p);
    actual->GetPoint(i, q);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(p[k], q[k]) << "point " << i;
  }
  auto want = vtkSmartPointer<vtkIdList>::New();
  auto got = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < expected->GetNumberOfCells(); ++c) {
    ASSERT_EQ(expected->GetCellType(c), actual->GetCellType(c)) << "cell " << c;
    expected->GetCellPoints(c, want);
    actual->GetCellPoints(c, got);
    ASSERT_EQ(want->GetNumberOfIds(), got->GetNumberOfIds()) << "cell " << c;
    for (vtkIdType k = 0; k < want->GetNumberOfIds(); ++k) ASSERT_EQ(want->GetId(k), got->GetId(k)) << "cell " << c;
  }
  expect_same_arrays(expected->GetPointData(), actual->GetPointData(), "point");
  expect_same_arrays(expected->GetCellData(), actual->GetCellData(), "cell");
}

}  // namespace fest::test

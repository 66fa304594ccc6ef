// The committed fixture tests/data/dataset/rotating_tets.vtu, checked against what
// its README says it holds.

#include <gtest/gtest.h>
#include <vtkCellType.h>
#include <vtkDataSet.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkCellData.h>

#include "test_dataset_vtk_adapter.hpp"
#include "testdata.hpp"

namespace fest::formats {
namespace {

TEST(DatasetFixture, RotatingTetsHoldsTheRotationField) {
  std::string bytes = test::slurp(test::fixture("dataset/rotating_tets.vtu"));
  ASSERT_FALSE(bytes.empty());
  vtkSmartPointer<vtkDataSet> grid = read_vtk(bytes, Format::vtu);
  ASSERT_EQ(grid->GetNumberOfPoints(), 5);
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  const vtkIdType tets[2][4] = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < 2; ++c) {
    EXPECT_EQ(grid->GetCellType(c), VTK_TETRA);
    grid->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 4);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(ids->GetId(k), tets[c][k]);
  }
  vtkDataArray* velocity = grid->GetPointData()->GetArray("velocity");
  ASSERT_NE(velocity, nullptr);
  ASSERT_EQ(velocity->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < 5; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    EXPECT_EQ(velocity->GetComponent(i, 0), -p[1]);
    EXPECT_EQ(velocity->GetComponent(i, 1), p[0]);
    EXPECT_EQ(velocity->GetComponent(i, 2), 0.0);
  }
  vtkDataArray* tet_id = grid->GetCellData()->GetArray("tet_id");
  ASSERT_NE(tet_id, nullptr);
  EXPECT_EQ(tet_id->GetComponent(0, 0), 0);
  EXPECT_EQ(tet_id->GetComponent(1, 0), 1);
}

TEST(DatasetFixture, RotatingTetsConvertsToLegacyAndBack) {
  vtkSmartPointer<vtkDataSet> grid = read_vtk(test::slurp(test::fixture("dataset/rotating_tets.vtu")), Format::vtu);
  for (bool ascii : {true, false}) {
    DatasetWriteOptions options;
    options.ascii = ascii;
    vtkSmartPointer<vtkDataSet> back = read_vtk(write_dataset(grid, Format::vtk, options), Format::vtk);
    EXPECT_EQ(back->GetNumberOfCells(), 2);
    EXPECT_EQ(back->GetPointData()->GetArray("velocity")->GetComponent(4, 0), -1.0);
  }
}

}  // namespace
}  // namespace fest::formats

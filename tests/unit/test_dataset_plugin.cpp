// fest::Dataset through the VTK plugin and back, and its geometry queries against VTK's
// own answers for the same dataset (vtkDataSet::GetPoint, GetCellType, GetCellPoints,
// GetBounds), so that code which left VTK keeps VTK's meaning.

#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <vtkIdList.h>
#include <vtkNew.h>

#include "core/dataset.hpp"
#include "test_dataset_samples.hpp"
#include "test_dataset_vtk_adapter.hpp"

using namespace fest;
using namespace fest::formats;

namespace {

Dataset two_cells() {
  Dataset d;
  d.kind = DatasetKind::unstructured;
  d.has_points = true;
  d.points = DataArray::from_doubles("Points", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
  const int64_t tet[] = {0, 1, 2, 3}, tri[] = {1, 2, 4};
  d.cells.push_back(tet, 4);
  d.cells.push_back(tri, 3);
  d.cell_types = {vtk_cell::tetra, vtk_cell::triangle};
  // A value float64 cannot hold: the int64 array must come back exactly.
  d.point_data.push_back(DataArray::from_ints("id", 1, {0, 1, 2, (int64_t(1) << 60) + 1, -7}, vtk_type::long_long));
  d.point_data.back().attribute = 0;  // active scalars
  d.cell_data.push_back(DataArray::from_doubles("c", 2, {0.5, -1, 2.25, 3}, vtk_type::float_));
  DataArray names;
  names.name = "labels";
  names.type = vtk_type::string;
  names.strings = {"first", "second"};
  names.value_count = 2;
  d.field_data.push_back(names);
  return d;
}

void expect_same(const DataArray& a, const DataArray& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.value_count, b.value_count);
  EXPECT_EQ(a.bytes, b.bytes) << a.name;
  EXPECT_EQ(a.strings, b.strings) << a.name;
  EXPECT_EQ(vtk_type_size(a.type), vtk_type_size(b.type)) << a.name;
}

}  // namespace

TEST(DatasetPlugin, UnstructuredRoundTripKeepsTypesIdsAndStrings) {
  const Dataset d = two_cells();
  for (Format f : {Format::vtu, Format::vtk})
    for (bool ascii : {false, true}) {
      DatasetWriteOptions options;
      options.ascii = ascii;
      const Dataset back = read_dataset(write_dataset(d, f, options), f);
      ASSERT_EQ(back.kind, DatasetKind::unstructured);
      EXPECT_EQ(back.cell_types, d.cell_types);
      EXPECT_EQ(back.cells.offsets, d.cells.offsets);
      EXPECT_EQ(back.cells.connectivity, d.cells.connectivity);
      ASSERT_EQ(back.point_data.size(), 1u);
      expect_same(back.point_data[0], d.point_data[0]);
      EXPECT_EQ(back.point_data[0].attribute, 0);
      EXPECT_EQ(back.point_data[0].value(3), double((int64_t(1) << 60) + 1));
      ASSERT_EQ(back.cell_data.size(), 1u);
      expect_same(back.cell_data[0], d.cell_data[0]);
      EXPECT_EQ(back.cell_data[0].type, vtk_type::float_);
      ASSERT_EQ(back.field_data.size(), 1u);
      expect_same(back.field_data[0], d.field_data[0]);
      for (std::size_t i = 0; i < d.point_count(); ++i) EXPECT_EQ(back.point(i), d.point(i));
    }
}

TEST(DatasetPlugin, PolyDataKeepsVtkCellOrder) {
  Dataset d;
  d.kind = DatasetKind::polydata;
  d.has_points = true;
  d.points = DataArray::from_floats("", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 9, 9, 9});
  const int64_t v[] = {4}, l[] = {0, 1, 3}, p[] = {0, 1, 3, 2}, s[] = {0, 1, 2, 3};
  d.verts.push_back(v, 1);
  d.lines.push_back(l, 3);
  d.polys.push_back(p, 4);
  d.strips.push_back(s, 4);
  const Dataset back = read_dataset(write_dataset(d, Format::vtp), Format::vtp);
  ASSERT_EQ(back.cell_count(), 4u);
  const uint8_t types[] = {vtk_cell::vertex, vtk_cell::poly_line, vtk_cell::quad, vtk_cell::triangle_strip};
  std::vector<int64_t> ids;
  for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(back.cell_type(c), types[c]) << c;
  back.cell_points(2, ids);
  EXPECT_EQ(ids, std::vector<int64_t>({0, 1, 3, 2}));
  EXPECT_EQ(back.bounds()[1], 9.0);
}

// Image data with a negative extent and a rotated, flipped direction matrix.
vtkSmartPointer<vtkDataSet> oriented_image() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(-2, 1, -1, 1, 0, 2);
  image->SetOrigin(1, 2, 3);
  image->SetSpacing(0.5, 2, 1);
  image->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, -1);
  return image;
}

// Polygonal data with a point no cell uses (it still counts for the bounds).
vtkSmartPointer<vtkDataSet> poly_with_unused_point() {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (double p : {0.0, 1.0, 7.0}) points->InsertNextPoint(p, p == 1.0 ? 0.0 : p, 0.0);
  points->InsertNextPoint(0, 1, 0);
  poly->SetPoints(points);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType tri[3] = {0, 1, 3};
  polys->InsertNextCell(3, tri);
  poly->SetPolys(polys);
  return poly;
}

// Every sample the VTK tests build: points, cells and bounds as VTK computes them.
TEST(DatasetPlugin, GeometryQueriesMatchVtk) {
  vtkSmartPointer<vtkDataSet> samples[] = {test::make_image(),          test::make_tets(),
                                           test::make_poly(),           test::make_structured_grid(),
                                           test::make_rectilinear_grid(), oriented_image(),
                                           poly_with_unused_point()};
  vtkNew<vtkIdList> vtk_ids;
  std::vector<int64_t> ids;
  for (vtkDataSet* vtk : samples) {
    const Dataset d = from_vtk(vtk);
    SCOPED_TRACE(vtk->GetClassName());
    ASSERT_EQ(d.point_count(), std::size_t(vtk->GetNumberOfPoints()));
    ASSERT_EQ(d.cell_count(), std::size_t(vtk->GetNumberOfCells()));
    for (vtkIdType i = 0; i < vtk->GetNumberOfPoints(); ++i) {
      double x[3];
      vtk->GetPoint(i, x);
      const auto p = d.point(std::size_t(i));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p[std::size_t(k)], x[k]);
    }
    for (vtkIdType c = 0; c < vtk->GetNumberOfCells(); ++c) {
      EXPECT_EQ(int(d.cell_type(std::size_t(c))), vtk->GetCellType(c));
      vtk->GetCellPoints(c, vtk_ids);
      d.cell_points(std::size_t(c), ids);
      ASSERT_EQ(ids.size(), std::size_t(vtk_ids->GetNumberOfIds()));
      for (std::size_t k = 0; k < ids.size(); ++k) EXPECT_EQ(ids[k], vtk_ids->GetId(vtkIdType(k)));
    }
    double b[6];
    vtk->GetBounds(b);
    const auto mine = d.bounds();
    for (int k = 0; k < 6; ++k) EXPECT_EQ(mine[std::size_t(k)], b[k]);
  }
}

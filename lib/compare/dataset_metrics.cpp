#include <algorithm>
#include <cmath>
#include <limits>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include "compare/dataset_compare.hpp"

namespace fest::compare {

namespace {

double value_difference(double x, double y) {
  if (std::isnan(x) || std::isnan(y))
    return (std::isnan(x) && std::isnan(y)) ? 0.0 : std::numeric_limits<double>::infinity();
  return x == y ? 0.0 : std::abs(x - y);
}

void compare_arrays(vtkFieldData* fa, vtkFieldData* fb, const std::string& prefix, DatasetDifference& d) {
  for (int i = 0; i < fa->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = fa->GetArray(i);
    if (a == nullptr || a->GetName() == nullptr) continue;  // string arrays: not numeric data
    vtkDataArray* b = fb->GetArray(a->GetName());
    if (b == nullptr || b->GetNumberOfTuples() != a->GetNumberOfTuples() ||
        b->GetNumberOfComponents() != a->GetNumberOfComponents()) {
      ++d.missing_arrays;
      continue;
    }
    double worst = 0;
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        worst = std::max(worst, value_difference(a->GetComponent(t, c), b->GetComponent(t, c)));
    d.array_max_abs[prefix + a->GetName()] = worst;
    d.array_max_abs_all = std::max(d.array_max_abs_all, worst);
  }
  for (int i = 0; i < fb->GetNumberOfArrays(); ++i) {
    vtkDataArray* b = fb->GetArray(i);
    if (b != nullptr && b->GetName() != nullptr && fa->GetArray(b->GetName()) == nullptr) ++d.missing_arrays;
  }
}

}  // namespace

DatasetDifference dataset_difference(vtkDataSet* a, vtkDataSet* b) {
  DatasetDifference d;
  d.points_a = static_cast<std::size_t>(a->GetNumberOfPoints());
  d.points_b = static_cast<std::size_t>(b->GetNumberOfPoints());
  d.cells_a = static_cast<std::size_t>(a->GetNumberOfCells());
  d.cells_b = static_cast<std::size_t>(b->GetNumberOfCells());
  const vtkIdType points = std::min(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points; ++i) {
    double pa[3], pb[3];
    a->GetPoint(i, pa);
    b->GetPoint(i, pb);
    for (int k = 0; k < 3; ++k) d.point_max_abs = std::max(d.point_max_abs, value_difference(pa[k], pb[k]));
  }
  const vtkIdType cells = std::min(a->GetNumberOfCells(), b->GetNumberOfCells());
  vtkNew<vtkIdList> ia, ib;
  for (vtkIdType i = 0; i < cells; ++i) {
    a->GetCellPoints(i, ia);
    b->GetCellPoints(i, ib);
    bool same = a->GetCellType(i) == b->GetCellType(i) && ia->GetNumberOfIds() == ib->GetNumberOfIds();
    for (vtkIdType k = 0; same && k < ia->GetNumberOfIds(); ++k) same = ia->GetId(k) == ib->GetId(k);
    if (!same) ++d.cell_diffs;
  }
  if (d.points_a == d.points_b) compare_arrays(a->GetPointData(), b->GetPointData(), "point:", d);
  if (d.cells_a == d.cells_b) compare_arrays(a->GetCellData(), b->GetCellData(), "cell:", d);
  return d;
}

}  // namespace fest::compare

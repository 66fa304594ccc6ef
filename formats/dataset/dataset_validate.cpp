#include "formats/dataset/dataset_validate.hpp"

#include <cstdint>
#include <cstring>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "lib/core/error.hpp"

namespace fest::formats::detail {
namespace {

constexpr int64_t kMaxGridPoints = int64_t{1} << 40;

// Points a cell of a fixed-size type must have; -1 for types of any size.
int points_per_cell(int type) {
  switch (type) {
    case VTK_VERTEX: return 1;
    case VTK_LINE: return 2;
    case VTK_TRIANGLE: return 3;
    case VTK_PIXEL:
    case VTK_QUAD:
    case VTK_TETRA: return 4;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON: return 8;
    case VTK_WEDGE: return 6;
    case VTK_PYRAMID: return 5;
    case VTK_PENTAGONAL_PRISM: return 10;
    case VTK_HEXAGONAL_PRISM: return 12;
    case VTK_QUADRATIC_EDGE: return 3;
    case VTK_QUADRATIC_TRIANGLE: return 6;
    case VTK_QUADRATIC_QUAD: return 8;
    case VTK_QUADRATIC_TETRA: return 10;
    case VTK_QUADRATIC_HEXAHEDRON: return 20;
    case VTK_QUADRATIC_WEDGE: return 15;
    case VTK_QUADRATIC_PYRAMID: return 13;
    case VTK_BIQUADRATIC_QUAD: return 9;
    case VTK_TRIQUADRATIC_HEXAHEDRON: return 27;
    case VTK_BIQUADRATIC_TRIANGLE: return 7;
    case VTK_CUBIC_LINE: return 4;
    default: return -1;
  }
}

// Offsets start at 0, never decrease and end at the connectivity length; every id
// names an existing point. Calls `each(cell, size)` for every cell.
template <typename Id, typename Each>
void check_cell_list(const Id* offsets, int64_t n_offsets, const Id* ids, int64_t n_ids, int64_t n_points,
                     const char* what, const char* format, Each each) {
  if (n_offsets == 0) {
    if (n_ids != 0) throw bad_input("{}: {} has {} point ids but no offsets", format, what, n_ids);
    return;
  }
  if (offsets[0] != 0) throw bad_input("{}: {} offsets start at {}, not 0", format, what, offsets[0]);
  for (int64_t i = 1; i < n_offsets; ++i) {
    if (offsets[i] < offsets[i - 1])
      throw bad_input("{}: {} offsets decrease at cell {}", format, what, i - 1);
    each(i - 1, static_cast<int64_t>(offsets[i] - offsets[i - 1]));
  }
  if (static_cast<int64_t>(offsets[n_offsets - 1]) != n_ids)
    throw bad_input("{}: {} offsets end at {} but there are {} point ids", format, what, offsets[n_offsets - 1],
                    n_ids);
  for (int64_t i = 0; i < n_ids; ++i)
    if (ids[i] < 0 || static_cast<int64_t>(ids[i]) >= n_points)
      throw bad_input("{}: {} refers to point {} of {}", format, what, ids[i], n_points);
}

template <typename Each>
void check_cells(vtkCellArray* cells, int64_t n_points, const char* what, const char* format, Each each) {
  if (cells == nullptr) return;
  if (cells->IsStorage64Bit()) {
    auto* offsets = cells->GetOffsetsArray64();
    auto* ids = cells->GetConnectivityArray64();
    check_cell_list(offsets->GetPointer(0), offsets->GetNumberOfValues(), ids->GetPointer(0),
                    ids->GetNumberOfValues(), n_points, what, format, each);
  } else {
    auto* offsets = cells->GetOffsetsArray32();
    auto* ids = cells->GetConnectivityArray32();
    check_cell_list(offsets->GetPointer(0), offsets->GetNumberOfValues(), ids->GetPointer(0),
                    ids->GetNumberOfValues(), n_points, what, format, each);
  }
}

void check_unstructured(vtkUnstructuredGrid* grid, int64_t n_points, const char* format) {
  vtkCellArray* cells = grid->GetCells();
  int64_t n_cells = cells ? cells->GetNumberOfCells() : 0;
  if (n_cells == 0) return;
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (types == nullptr || types->GetNumberOfValues() != n_cells)
    throw bad_input("{}: {} cells but {} cell types", format, n_cells, types ? types->GetNumberOfValues() : 0);
  check_cells(cells, n_points, "cell list", format, [&](int64_t cell, int64_t size) {
    int type = types->GetValue(cell);
    if (type == VTK_POLYHEDRON) throw bad_input("{}: cell {} is a polyhedron, which is not supported", format, cell);
    if (std::strcmp(vtkCellTypes::GetClassNameFromTypeId(type), "UnknownClass") == 0)
      throw bad_input("{}: cell {} has type {}, which VTK does not know", format, cell, type);
    int expected = points_per_cell(type);
    if (expected >= 0 && size != expected)
      throw bad_input("{}: cell {} of type {} has {} points instead of {}", format, cell,
                      vtkCellTypes::GetClassNameFromTypeId(type), size, expected);
  });
}

void check_poly(vtkPolyData* poly, int64_t n_points, const char* format) {
  auto any_size = [](int64_t, int64_t) {};
  check_cells(poly->GetVerts(), n_points, "vertex list", format, any_size);
  check_cells(poly->GetLines(), n_points, "line list", format, any_size);
  check_cells(poly->GetPolys(), n_points, "polygon list", format, any_size);
  check_cells(poly->GetStrips(), n_points, "triangle strip list", format, any_size);
}

int64_t grid_points(const int dims[3], const char* format) {
  int64_t n = 1;
  for (int axis = 0; axis < 3; ++axis) {
    if (dims[axis] < 0) throw bad_input("{}: negative grid dimension {}", format, dims[axis]);
    n *= dims[axis];
    if (n > kMaxGridPoints) throw bad_input("{}: grid of more than 2^40 points", format);
  }
  return n;
}

void check_attributes(vtkDataSetAttributes* data, int64_t expected, const char* kind, const char* format) {
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    if (array == nullptr) continue;
    if (array->GetNumberOfTuples() != expected)
      throw bad_input("{}: {} array '{}' has {} tuples for {} {}s", format, kind,
                      array->GetName() ? array->GetName() : "", array->GetNumberOfTuples(), expected, kind);
  }
}

}  // namespace

void validate_dataset(vtkDataSet* dataset, const char* format) {
  if (auto* image = vtkImageData::SafeDownCast(dataset)) {
    int extent[6];
    image->GetExtent(extent);
    int dims[3];
    for (int axis = 0; axis < 3; ++axis) {
      long long span = static_cast<long long>(extent[2 * axis + 1]) - extent[2 * axis] + 1;
      dims[axis] = span < 0 ? 0 : span > (1LL << 31) - 1 ? -1 : static_cast<int>(span);
    }
    grid_points(dims, format);
  } else if (auto* structured = vtkStructuredGrid::SafeDownCast(dataset)) {
    int64_t expected = grid_points(structured->GetDimensions(), format);
    if (structured->GetNumberOfPoints() != expected)
      throw bad_input("{}: structured grid of {} points has {} point coordinates", format, expected,
                      structured->GetNumberOfPoints());
  } else if (auto* rectilinear = vtkRectilinearGrid::SafeDownCast(dataset)) {
    int* dims = rectilinear->GetDimensions();
    if (grid_points(dims, format) > 0) {
      vtkDataArray* axes[3] = {rectilinear->GetXCoordinates(), rectilinear->GetYCoordinates(),
                               rectilinear->GetZCoordinates()};
      for (int axis = 0; axis < 3; ++axis)
        if (axes[axis] == nullptr || axes[axis]->GetNumberOfTuples() != dims[axis])
          throw bad_input("{}: rectilinear grid axis {} has {} coordinates for dimension {}", format, axis,
                          axes[axis] ? axes[axis]->GetNumberOfTuples() : 0, dims[axis]);
    }
  }

  const int64_t n_points = dataset->GetNumberOfPoints();
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(dataset)) check_unstructured(grid, n_points, format);
  if (auto* poly = vtkPolyData::SafeDownCast(dataset)) check_poly(poly, n_points, format);

  check_attributes(dataset->GetPointData(), n_points, "point", format);
  check_attributes(dataset->GetCellData(), dataset->GetNumberOfCells(), "cell", format);
}

}  // namespace fest::formats::detail

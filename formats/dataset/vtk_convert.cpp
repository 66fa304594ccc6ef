#include "formats/dataset/vtk_convert.hpp"

#include <cstring>
#include <string>

#include <vtkBitArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredPoints.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/error.hpp"

namespace fest::formats {
namespace {

std::size_t byte_count(int type, std::size_t values) {
  return type == vtk_type::bit ? (values + 7) / 8 : values * vtk_type_size(type);
}

DataArray array_from_vtk(vtkAbstractArray* array, const char* format, const char* where) {
  DataArray a;
  if (array->GetName()) a.name = array->GetName();
  a.components = array->GetNumberOfComponents();
  a.type = array->GetDataType();
  a.value_count = static_cast<std::size_t>(array->GetNumberOfValues());
  if (array->HasAComponentName())
    for (int c = 0; c < a.components; ++c) {
      const char* n = array->GetComponentName(c);
      a.component_names.push_back(n ? n : "");
    }
  if (auto* strings = vtkStringArray::SafeDownCast(array)) {
    a.type = vtk_type::string;
    for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i) a.strings.push_back(strings->GetValue(i));
    return a;
  }
  auto* numeric = vtkDataArray::SafeDownCast(array);
  if (numeric == nullptr || (a.type != vtk_type::bit && vtk_type_size(a.type) == 0))
    throw bad_input("{}: {} array '{}' is of type {}, which fest cannot carry", format, where, a.name,
                    array->GetDataTypeAsString());
  if (vtkScalarsToColors* colors = numeric->GetLookupTable()) {
    auto* lut = vtkLookupTable::SafeDownCast(colors);
    if (lut == nullptr)
      throw bad_input("{}: {} array '{}' has a {}, which fest cannot carry", format, where, a.name,
                      colors->GetClassName());
    const vtkIdType n = lut->GetNumberOfTableValues();
    a.lookup_table.resize(std::size_t(n) * 4);
    if (n > 0) std::memcpy(a.lookup_table.data(), lut->GetPointer(0), a.lookup_table.size());
  }
  a.bytes.resize(byte_count(a.type, a.value_count));
  if (!a.bytes.empty()) std::memcpy(a.bytes.data(), numeric->GetVoidPointer(0), a.bytes.size());
  return a;
}

std::vector<DataArray> arrays_from_vtk(vtkFieldData* data, const char* format, const char* where) {
  std::vector<DataArray> out;
  if (data == nullptr) return out;
  auto* attributes = vtkDataSetAttributes::SafeDownCast(data);
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    if (array == nullptr) continue;
    out.push_back(array_from_vtk(array, format, where));
    if (attributes) out.back().attribute = attributes->IsArrayAnAttribute(i);
  }
  return out;
}

CellArray cells_from_vtk(vtkCellArray* cells) {
  CellArray c;
  if (cells == nullptr) return c;
  c.ids_64bit = cells->IsStorage64Bit();
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  c.offsets.resize(static_cast<std::size_t>(offsets->GetNumberOfValues()));
  for (std::size_t i = 0; i < c.offsets.size(); ++i)
    c.offsets[i] = static_cast<int64_t>(offsets->GetTuple1(static_cast<vtkIdType>(i)));
  c.connectivity.resize(static_cast<std::size_t>(connectivity->GetNumberOfValues()));
  if (c.ids_64bit) {
    auto* ids = vtkTypeInt64Array::SafeDownCast(connectivity);
    if (ids && !c.connectivity.empty())
      std::memcpy(c.connectivity.data(), ids->GetPointer(0), c.connectivity.size() * sizeof(int64_t));
  } else {
    for (std::size_t i = 0; i < c.connectivity.size(); ++i)
      c.connectivity[i] = static_cast<int64_t>(connectivity->GetTuple1(static_cast<vtkIdType>(i)));
  }
  return c;
}

vtkSmartPointer<vtkAbstractArray> array_to_vtk(const DataArray& a) {
  vtkSmartPointer<vtkAbstractArray> array;
  array.TakeReference(vtkAbstractArray::CreateArray(a.type));
  if (!a.name.empty()) array->SetName(a.name.c_str());
  array->SetNumberOfComponents(a.components);
  for (std::size_t c = 0; c < a.component_names.size(); ++c)
    array->SetComponentName(static_cast<vtkIdType>(c), a.component_names[c].c_str());
  array->SetNumberOfTuples(static_cast<vtkIdType>(a.tuples()));
  if (auto* strings = vtkStringArray::SafeDownCast(array)) {
    for (std::size_t i = 0; i < a.strings.size(); ++i) strings->SetValue(static_cast<vtkIdType>(i), a.strings[i]);
  } else if (!a.bytes.empty()) {
    std::memcpy(array->GetVoidPointer(0), a.bytes.data(), a.bytes.size());
  }
  if (auto* numeric = vtkDataArray::SafeDownCast(array); numeric && !a.lookup_table.empty()) {
    auto lut = vtkSmartPointer<vtkLookupTable>::New();
    const std::size_t n = a.lookup_table.size() / 4;
    lut->SetNumberOfTableValues(static_cast<vtkIdType>(n));
    // c / 255 goes back to c exactly (SetTableValue rounds x * 255 to the nearest byte).
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* c = &a.lookup_table[4 * i];
      lut->SetTableValue(static_cast<vtkIdType>(i), c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
    }
    numeric->SetLookupTable(lut);
  }
  return array;
}

void arrays_to_vtk(const std::vector<DataArray>& arrays, vtkFieldData* data) {
  auto* attributes = vtkDataSetAttributes::SafeDownCast(data);
  for (const DataArray& a : arrays) {
    const int index = data->AddArray(array_to_vtk(a));
    if (attributes && a.attribute >= 0) attributes->SetActiveAttribute(index, a.attribute);
  }
}

vtkSmartPointer<vtkCellArray> cells_to_vtk(const CellArray& c) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  std::vector<int64_t> offsets = c.offsets;
  if (offsets.empty()) offsets.push_back(0);
  if (c.ids_64bit) {
    auto o = vtkSmartPointer<vtkTypeInt64Array>::New();
    auto k = vtkSmartPointer<vtkTypeInt64Array>::New();
    o->SetNumberOfValues(static_cast<vtkIdType>(offsets.size()));
    std::memcpy(o->GetPointer(0), offsets.data(), offsets.size() * sizeof(int64_t));
    k->SetNumberOfValues(static_cast<vtkIdType>(c.connectivity.size()));
    if (!c.connectivity.empty())
      std::memcpy(k->GetPointer(0), c.connectivity.data(), c.connectivity.size() * sizeof(int64_t));
    cells->SetData(o, k);
  } else {
    auto o = vtkSmartPointer<vtkTypeInt32Array>::New();
    auto k = vtkSmartPointer<vtkTypeInt32Array>::New();
    o->SetNumberOfValues(static_cast<vtkIdType>(offsets.size()));
    for (std::size_t i = 0; i < offsets.size(); ++i) o->SetValue(static_cast<vtkIdType>(i), static_cast<vtkTypeInt32>(offsets[i]));
    k->SetNumberOfValues(static_cast<vtkIdType>(c.connectivity.size()));
    for (std::size_t i = 0; i < c.connectivity.size(); ++i)
      k->SetValue(static_cast<vtkIdType>(i), static_cast<vtkTypeInt32>(c.connectivity[i]));
    cells->SetData(o, k);
  }
  return cells;
}

vtkSmartPointer<vtkPoints> points_to_vtk(const DataArray& a) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(vtkDataArray::SafeDownCast(array_to_vtk(a)));
  return points;
}

}  // namespace

Dataset from_vtk(vtkDataSet* input, const char* format) {
  Dataset d;
  if (auto* image = vtkImageData::SafeDownCast(input)) {
    d.kind = DatasetKind::image;
    d.structured_points = input->IsA("vtkStructuredPoints") != 0;
    image->GetExtent(d.extent.data());
    image->GetOrigin(d.origin.data());
    image->GetSpacing(d.spacing.data());
    const double* m = image->GetDirectionMatrix()->GetData();
    for (int i = 0; i < 9; ++i) d.direction[std::size_t(i)] = m[i];
  } else if (auto* rect = vtkRectilinearGrid::SafeDownCast(input)) {
    d.kind = DatasetKind::rectilinear;
    rect->GetExtent(d.extent.data());
    if (rect->GetXCoordinates()) d.x_coordinates = array_from_vtk(rect->GetXCoordinates(), format, "x coordinate");
    if (rect->GetYCoordinates()) d.y_coordinates = array_from_vtk(rect->GetYCoordinates(), format, "y coordinate");
    if (rect->GetZCoordinates()) d.z_coordinates = array_from_vtk(rect->GetZCoordinates(), format, "z coordinate");
  } else if (auto* grid = vtkStructuredGrid::SafeDownCast(input)) {
    d.kind = DatasetKind::structured;
    grid->GetExtent(d.extent.data());
  } else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(input)) {
    d.kind = DatasetKind::unstructured;
    if (ug->GetFaces() != nullptr && ug->GetFaces()->GetNumberOfValues() > 0)
      throw bad_input("{}: {} polyhedron face values, which fest cannot carry", format, ug->GetFaces()->GetNumberOfValues());
    if (vtkUnsignedCharArray* types = ug->GetCellTypesArray())
      for (vtkIdType i = 0; i < types->GetNumberOfValues(); ++i) d.cell_types.push_back(types->GetValue(i));
    d.cells = cells_from_vtk(ug->GetCells());
  } else if (auto* poly = vtkPolyData::SafeDownCast(input)) {
    d.kind = DatasetKind::polydata;
    d.verts = cells_from_vtk(poly->GetVerts());
    d.lines = cells_from_vtk(poly->GetLines());
    d.polys = cells_from_vtk(poly->GetPolys());
    d.strips = cells_from_vtk(poly->GetStrips());
  } else {
    throw bad_input("{}: a {} is not a dataset fest can carry", format, input ? input->GetClassName() : "null");
  }
  if (auto* set = vtkPointSet::SafeDownCast(input); set && set->GetPoints()) {
    d.has_points = true;
    d.points = array_from_vtk(set->GetPoints()->GetData(), format, "point coordinate");
  }
  d.point_data = arrays_from_vtk(input->GetPointData(), format, "point");
  d.cell_data = arrays_from_vtk(input->GetCellData(), format, "cell");
  d.field_data = arrays_from_vtk(input->GetFieldData(), format, "field");
  return d;
}

vtkSmartPointer<vtkDataSet> to_vtk(const Dataset& d) {
  vtkSmartPointer<vtkDataSet> out;
  switch (d.kind) {
    case DatasetKind::image: {
      vtkSmartPointer<vtkImageData> image;
      if (d.structured_points) image = vtkSmartPointer<vtkStructuredPoints>::New();
      else image = vtkSmartPointer<vtkImageData>::New();
      image->SetExtent(const_cast<int*>(d.extent.data()));
      image->SetOrigin(d.origin.data());
      image->SetSpacing(d.spacing.data());
      image->SetDirectionMatrix(d.direction.data());
      out = image;
      break;
    }
    case DatasetKind::rectilinear: {
      auto rect = vtkSmartPointer<vtkRectilinearGrid>::New();
      rect->SetExtent(const_cast<int*>(d.extent.data()));
      rect->SetXCoordinates(vtkDataArray::SafeDownCast(array_to_vtk(d.x_coordinates)));
      rect->SetYCoordinates(vtkDataArray::SafeDownCast(array_to_vtk(d.y_coordinates)));
      rect->SetZCoordinates(vtkDataArray::SafeDownCast(array_to_vtk(d.z_coordinates)));
      out = rect;
      break;
    }
    case DatasetKind::structured: {
      auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
      grid->SetExtent(const_cast<int*>(d.extent.data()));
      out = grid;
      break;
    }
    case DatasetKind::unstructured: {
      auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
      auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
      types->SetNumberOfValues(static_cast<vtkIdType>(d.cell_types.size()));
      if (!d.cell_types.empty()) std::memcpy(types->GetPointer(0), d.cell_types.data(), d.cell_types.size());
      ug->SetCells(types, cells_to_vtk(d.cells));
      out = ug;
      break;
    }
    case DatasetKind::polydata: {
      auto poly = vtkSmartPointer<vtkPolyData>::New();
      poly->SetVerts(cells_to_vtk(d.verts));
      poly->SetLines(cells_to_vtk(d.lines));
      poly->SetPolys(cells_to_vtk(d.polys));
      poly->SetStrips(cells_to_vtk(d.strips));
      out = poly;
      break;
    }
  }
  if (auto* set = vtkPointSet::SafeDownCast(out); set && d.has_points) set->SetPoints(points_to_vtk(d.points));
  arrays_to_vtk(d.point_data, out->GetPointData());
  arrays_to_vtk(d.cell_data, out->GetCellData());
  arrays_to_vtk(d.field_data, out->GetFieldData());
  return out;
}

}  // namespace fest::formats

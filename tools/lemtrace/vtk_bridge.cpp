#include "vtk_bridge.hpp"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/error.hpp"
#include "lemtrace/vtk/tet_grid.hpp"

namespace fest::lemtrace_tool {
namespace {

std::string three_component_names(vtkFieldData* data) {
  std::string names;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = data->GetArray(i);
    if (a == nullptr || a->GetNumberOfComponents() != 3) continue;
    if (!names.empty()) names += ", ";
    names += a->GetName() ? a->GetName() : "(unnamed)";
  }
  return names;
}

vtkDataArray* pick_vectors(vtkDataSet* ds, const std::string& wanted) {
  vtkPointData* pd = ds->GetPointData();
  vtkCellData* cd = ds->GetCellData();
  if (!wanted.empty()) {
    vtkDataArray* a = pd->GetArray(wanted.c_str());
    if (a == nullptr) {
      if (cd->GetArray(wanted.c_str()) != nullptr)
        throw bad_input("'{}' is cell data; lemtrace needs point vectors; use a cell-to-point filter", wanted);
      const std::string names = three_component_names(pd);
      throw bad_input("no point array named '{}' (3-component point arrays: {})", wanted,
                      names.empty() ? "none" : names);
    }
    if (a->GetNumberOfComponents() != 3)
      throw bad_input("point array '{}' has {} components; lemtrace needs 3-component vectors", wanted,
                      a->GetNumberOfComponents());
    return a;
  }
  if (vtkDataArray* active = pd->GetVectors(); active != nullptr && active->GetNumberOfComponents() == 3) return active;
  vtkDataArray* only = nullptr;
  int count = 0;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = pd->GetArray(i);
    if (a != nullptr && a->GetNumberOfComponents() == 3) {
      only = a;
      ++count;
    }
  }
  if (count == 1) return only;
  if (count > 1)
    throw bad_input("several 3-component point arrays ({}); pick one with --vectors", three_component_names(pd));
  if (!three_component_names(cd).empty())
    throw bad_input("the vectors ({}) are cell data; lemtrace needs point vectors; use a cell-to-point filter",
                    three_component_names(cd));
  throw bad_input("no 3-component point array (vectors) in the grid");
}

void read_field_data(vtkDataSet* ds, LoadedGrid& out) {
  vtkFieldData* fd = ds->GetFieldData();
  if (fd == nullptr) return;
  auto* kind = vtkStringArray::SafeDownCast(fd->GetAbstractArray("LemtraceKind"));
  vtkDataArray* A = fd->GetArray("LemtraceA");
  vtkDataArray* b = fd->GetArray("LemtraceB");
  if (kind && kind->GetNumberOfValues() == 1) out.kind = kind->GetValue(0);
  if (A && b && A->GetNumberOfValues() == 9 && b->GetNumberOfValues() == 3) {
    out.linear = true;
    for (int i = 0; i < 9; ++i) out.field.A(i / 3, i % 3) = A->GetVariantValue(i).ToDouble();
    for (int i = 0; i < 3; ++i) out.field.b[i] = b->GetVariantValue(i).ToDouble();
  }
}

void structured_cells(const int dims[3], RawCells& cells) {
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
    throw bad_input("the structured grid is {}x{}x{} points; lemtrace needs a 3-D grid (2-D mode is not available)",
                    dims[0], dims[1], dims[2]);
  const int64_t nx = dims[0], ny = dims[1];
  auto id = [&](int64_t i, int64_t j, int64_t k) { return (k * ny + j) * nx + i; };
  for (int64_t k = 0; k + 1 < dims[2]; ++k)
    for (int64_t j = 0; j + 1 < dims[1]; ++j)
      for (int64_t i = 0; i + 1 < dims[0]; ++i)
        cells.add(static_cast<uint8_t>(CellShape::hexahedron),
                  {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                   id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
}

}  // namespace

LoadedGrid grid_from_dataset(vtkDataSet* ds, const std::string& vectors_name) {
  LoadedGrid out;
  if (ds->IsA("vtkPolyData") || ds->IsA("vtkRectilinearGrid"))
    throw bad_input("the grid is a {}; lemtrace reads unstructured grids, image data and structured grids",
                    ds->GetClassName());
  vtkDataArray* vec = pick_vectors(ds, vectors_name);
  out.vector_name = vec->GetName() ? vec->GetName() : "";
  const vtkIdType n = ds->GetNumberOfPoints();
  out.points.resize(static_cast<std::size_t>(n));
  out.vectors.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3], v[3];
    ds->GetPoint(i, p);
    vec->GetTuple(i, v);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(v[a]))
        throw bad_input("vector array '{}' has a non-finite value ({}) at point {}", out.vector_name, v[a], i);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(p[a])) throw bad_input("point {} has a non-finite coordinate", i);
    out.points[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
    out.vectors[static_cast<std::size_t>(i)] = Vec3(v[0], v[1], v[2]);
  }
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds)) {
    auto ids = vtkSmartPointer<vtkIdList>::New();
    out.cells.offsets.reserve(static_cast<std::size_t>(ug->GetNumberOfCells()) + 1);
    out.cells.offsets.push_back(0);
    for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c) {
      ug->GetCellPoints(c, ids);
      out.cells.types.push_back(static_cast<uint8_t>(ug->GetCellType(c)));
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) out.cells.ids.push_back(ids->GetId(k));
      out.cells.offsets.push_back(static_cast<int64_t>(out.cells.ids.size()));
    }
  } else if (auto* image = vtkImageData::SafeDownCast(ds)) {
    int dims[3];
    image->GetDimensions(dims);
    structured_cells(dims, out.cells);
  } else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds)) {
    int dims[3];
    sg->GetDimensions(dims);
    structured_cells(dims, out.cells);
  } else {
    throw bad_input("lemtrace cannot trace in a {}", ds->GetClassName());
  }
  if (out.cells.size() == 0) throw bad_input("the grid has no cells");
  read_field_data(ds, out);
  return out;
}

vtkSmartPointer<vtkUnstructuredGrid> dataset_from_generated(const GeneratedGrid& g, const std::string& kind) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(g.points.size()));
  auto vel = vtkSmartPointer<vtkDoubleArray>::New();
  vel->SetName("velocity");
  vel->SetNumberOfComponents(3);
  vel->SetNumberOfTuples(static_cast<vtkIdType>(g.points.size()));
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), g.points[i].data());
    vel->SetTuple(static_cast<vtkIdType>(i), g.vectors[i].data());
  }
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(g.cells.size()));
  std::vector<vtkIdType> ids;
  for (std::size_t c = 0; c < g.cells.size(); ++c) {
    ids.assign(g.cells.ids.begin() + g.cells.offsets[c], g.cells.ids.begin() + g.cells.offsets[c + 1]);
    grid->InsertNextCell(g.cells.types[c], static_cast<vtkIdType>(ids.size()), ids.data());
  }
  grid->GetPointData()->SetVectors(vel);
  auto name = vtkSmartPointer<vtkStringArray>::New();
  name->SetName("LemtraceKind");
  name->InsertNextValue(kind);
  grid->GetFieldData()->AddArray(name);
  if (g.linear) {
    auto A = vtkSmartPointer<vtkDoubleArray>::New();
    A->SetName("LemtraceA");
    for (int i = 0; i < 9; ++i) A->InsertNextValue(g.field.A(i / 3, i % 3));
    auto b = vtkSmartPointer<vtkDoubleArray>::New();
    b->SetName("LemtraceB");
    for (int i = 0; i < 3; ++i) b->InsertNextValue(g.field.b[i]);
    grid->GetFieldData()->AddArray(A);
    grid->GetFieldData()->AddArray(b);
  }
  return grid;
}

Vec3 velocity_at(const FieldGrid& grid, int32_t cell, const Vec3& x) {
  const TetGeometry g = tet_geometry(grid.mesh(), cell);
  return g.interpolate(g.bary(x));
}

vtkSmartPointer<vtkPolyData> polylines_to_dataset(const FieldGrid& grid, const LineSet& set) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto time = vtkSmartPointer<vtkDoubleArray>::New();
  time->SetName("IntegrationTime");
  auto cell_id = vtkSmartPointer<vtkIdTypeArray>::New();
  cell_id->SetName("CellId");
  auto speed = vtkSmartPointer<vtkDoubleArray>::New();
  speed->SetName("Speed");
  auto velocity = vtkSmartPointer<vtkDoubleArray>::New();
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  auto seed_id = vtkSmartPointer<vtkIdTypeArray>::New();
  seed_id->SetName("SeedId");
  auto reason = vtkSmartPointer<vtkIntArray>::New();
  reason->SetName("ReasonForTermination");
  auto n_cells = vtkSmartPointer<vtkIdTypeArray>::New();
  n_cells->SetName("NumberOfCells");
  const auto& all = *set.lines;
  for (std::size_t l = 0; l < all.size(); ++l) {
    const Polyline& line = all[l];
    if (line.x.empty()) continue;  // a seed outside the grid has no points
    lines->InsertNextCell(static_cast<vtkIdType>(line.x.size()));
    for (std::size_t i = 0; i < line.x.size(); ++i) {
      lines->InsertCellPoint(points->InsertNextPoint(line.x[i].data()));
      time->InsertNextValue(line.t[i]);
      const int32_t c = line.cell[i];
      cell_id->InsertNextValue(grid.mesh().source_cell[static_cast<std::size_t>(c)]);
      const Vec3 v = velocity_at(grid, c, line.x[i]);
      speed->InsertNextValue(v.norm());
      velocity->InsertNextTuple(v.data());
    }
    seed_id->InsertNextValue(static_cast<vtkIdType>((*set.seed_ids)[l]));
    reason->InsertNextValue(static_cast<int>(line.reason));
    n_cells->InsertNextValue(line.cells);
  }
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->GetPointData()->AddArray(time);
  poly->GetPointData()->AddArray(cell_id);
  poly->GetPointData()->AddArray(speed);
  poly->GetPointData()->AddArray(velocity);
  poly->GetCellData()->AddArray(seed_id);
  poly->GetCellData()->AddArray(reason);
  poly->GetCellData()->AddArray(n_cells);
  auto opts = vtkSmartPointer<vtkStringArray>::New();
  opts->SetName("LemtraceOptions");
  opts->InsertNextValue(set.options);
  poly->GetFieldData()->AddArray(opts);
  return poly;
}

vtkSmartPointer<vtkUnstructuredGrid> classified_dataset(const FieldGrid& grid, const std::vector<CellRecord>& records) {
  const TetMesh& mesh = grid.mesh();
  vtkSmartPointer<vtkUnstructuredGrid> ug = tet_mesh_to_vtk(mesh);
  auto type = vtkSmartPointer<vtkUnsignedCharArray>::New();
  type->SetName("LemType");
  auto eig = vtkSmartPointer<vtkDoubleArray>::New();
  eig->SetName("Eigenvalues");
  eig->SetNumberOfComponents(3);
  auto crit = vtkSmartPointer<vtkUnsignedCharArray>::New();
  crit->SetName("CriticalPointInside");
  for (std::size_t c = 0; c < mesh.tets.size(); ++c) {
    const CellRecord& r = records[c];
    type->InsertNextValue(static_cast<unsigned char>(r.type));
    const bool normal = r.type == CellType::normal_real || r.type == CellType::normal_complex;
    double e[3] = {NAN, NAN, NAN};
    if (normal) e[0] = r.lam[0], e[1] = r.lam[1], e[2] = r.lam[2];
    eig->InsertNextTuple(e);
    crit->InsertNextValue(r.critical_inside ? 1 : 0);
  }
  ug->GetCellData()->AddArray(type);
  ug->GetCellData()->AddArray(eig);
  ug->GetCellData()->AddArray(crit);
  return ug;
}

std::vector<Vec3> points_of(vtkDataSet* dataset) {
  std::vector<Vec3> out;
  for (vtkIdType i = 0; i < dataset->GetNumberOfPoints(); ++i) {
    double p[3];
    dataset->GetPoint(i, p);
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

}  // namespace fest::lemtrace_tool

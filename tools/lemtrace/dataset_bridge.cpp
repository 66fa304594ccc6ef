#include "dataset_bridge.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::lemtrace_tool {
namespace {

// vtkFieldData::GetArray(name): the first array of that name, when it is numeric.
const DataArray* numeric_array(const std::vector<DataArray>& arrays, const std::string& name) {
  for (const DataArray& a : arrays)
    if (a.name == name) return a.numeric() ? &a : nullptr;
  return nullptr;
}

std::string three_component_names(const std::vector<DataArray>& arrays) {
  std::string names;
  for (const DataArray& a : arrays) {
    if (!a.numeric() || a.components != 3) continue;
    if (!names.empty()) names += ", ";
    names += a.name.empty() ? "(unnamed)" : a.name;
  }
  return names;
}

const DataArray& pick_vectors(const Dataset& ds, const std::string& wanted) {
  const std::vector<DataArray>& pd = ds.point_data;
  const std::vector<DataArray>& cd = ds.cell_data;
  if (!wanted.empty()) {
    const DataArray* a = numeric_array(pd, wanted);
    if (a == nullptr) {
      if (numeric_array(cd, wanted) != nullptr)
        throw bad_input("'{}' is cell data; lemtrace needs point vectors; use a cell-to-point filter", wanted);
      const std::string names = three_component_names(pd);
      throw bad_input("no point array named '{}' (3-component point arrays: {})", wanted,
                      names.empty() ? "none" : names);
    }
    if (a->components != 3)
      throw bad_input("point array '{}' has {} components; lemtrace needs 3-component vectors", wanted, a->components);
    return *a;
  }
  for (const DataArray& a : pd)
    if (a.attribute == 1 && a.numeric() && a.components == 3) return a;  // the active vectors
  const DataArray* only = nullptr;
  int count = 0;
  for (const DataArray& a : pd) {
    if (a.numeric() && a.components == 3) {
      only = &a;
      ++count;
    }
  }
  if (count == 1) return *only;
  if (count > 1)
    throw bad_input("several 3-component point arrays ({}); pick one with --vectors", three_component_names(pd));
  if (!three_component_names(cd).empty())
    throw bad_input("the vectors ({}) are cell data; lemtrace needs point vectors; use a cell-to-point filter",
                    three_component_names(cd));
  throw bad_input("no 3-component point array (vectors) in the grid");
}

void read_field_data(const Dataset& ds, LoadedGrid& out) {
  const DataArray* kind = nullptr;
  for (const DataArray& a : ds.field_data)
    if (a.name == "LemtraceKind") {
      kind = &a;
      break;
    }
  const DataArray* A = numeric_array(ds.field_data, "LemtraceA");
  const DataArray* b = numeric_array(ds.field_data, "LemtraceB");
  if (kind && !kind->numeric() && kind->strings.size() == 1) out.kind = kind->strings[0];
  if (A && b && A->value_count == 9 && b->value_count == 3) {
    out.linear = true;
    for (int i = 0; i < 9; ++i) out.field.A(i / 3, i % 3) = A->value(std::size_t(i));
    for (int i = 0; i < 3; ++i) out.field.b[i] = b->value(std::size_t(i));
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

LoadedGrid grid_from_dataset(const Dataset& ds, const std::string& vectors_name) {
  LoadedGrid out;
  if (ds.kind == DatasetKind::polydata || ds.kind == DatasetKind::rectilinear)
    throw bad_input("the grid is a {}; lemtrace reads unstructured grids, image data and structured grids",
                    ds.class_name());
  const DataArray& vec = pick_vectors(ds, vectors_name);
  out.vector_name = vec.name;
  const std::size_t n = ds.point_count();
  out.points.resize(n);
  out.vectors.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = ds.point(i);
    const double v[3] = {vec.component(i, 0), vec.component(i, 1), vec.component(i, 2)};
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(v[a]))
        throw bad_input("vector array '{}' has a non-finite value ({}) at point {}", out.vector_name, v[a], i);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(p[std::size_t(a)])) throw bad_input("point {} has a non-finite coordinate", i);
    out.points[i] = Vec3(p[0], p[1], p[2]);
    out.vectors[i] = Vec3(v[0], v[1], v[2]);
  }
  if (ds.kind == DatasetKind::unstructured) {
    out.cells.types = ds.cell_types;
    out.cells.offsets = ds.cells.offsets;
    if (out.cells.offsets.empty()) out.cells.offsets.push_back(0);
    out.cells.ids = ds.cells.connectivity;
  } else if (ds.kind == DatasetKind::image || ds.kind == DatasetKind::structured) {
    const auto dims = ds.dimensions();
    structured_cells(dims.data(), out.cells);
  } else {
    throw bad_input("lemtrace cannot trace in a {}", ds.class_name());
  }
  if (out.cells.size() == 0) throw bad_input("the grid has no cells");
  read_field_data(ds, out);
  return out;
}

namespace {

DataArray vec3_array(std::string name, const std::vector<Vec3>& values) {
  std::vector<double> flat;
  flat.reserve(3 * values.size());
  for (const Vec3& v : values) flat.insert(flat.end(), {v[0], v[1], v[2]});
  return DataArray::from_doubles(std::move(name), 3, flat);
}

DataArray string_array(std::string name, std::string value) {
  DataArray a;
  a.name = std::move(name);
  a.type = vtk_type::string;
  a.strings = {std::move(value)};
  a.value_count = 1;
  return a;
}

}  // namespace

Dataset dataset_from_generated(const GeneratedGrid& g, const std::string& kind) {
  Dataset grid;
  grid.kind = DatasetKind::unstructured;
  grid.has_points = true;
  grid.points = vec3_array("Points", g.points);
  for (std::size_t c = 0; c < g.cells.size(); ++c)
    grid.cells.push_back(g.cells.ids.data() + g.cells.offsets[c], std::size_t(g.cells.offsets[c + 1] - g.cells.offsets[c]));
  grid.cell_types = g.cells.types;
  grid.point_data.push_back(vec3_array("velocity", g.vectors));
  grid.point_data.back().attribute = 1;  // active vectors
  grid.field_data.push_back(string_array("LemtraceKind", kind));
  if (g.linear) {
    std::vector<double> A, b;
    for (int i = 0; i < 9; ++i) A.push_back(g.field.A(i / 3, i % 3));
    for (int i = 0; i < 3; ++i) b.push_back(g.field.b[i]);
    grid.field_data.push_back(DataArray::from_doubles("LemtraceA", 1, A));
    grid.field_data.push_back(DataArray::from_doubles("LemtraceB", 1, b));
  }
  return grid;
}

Vec3 velocity_at(const FieldGrid& grid, int32_t cell, const Vec3& x) { return velocity_in_cell(grid.mesh(), cell, x); }

Dataset polylines_to_dataset(const FieldGrid& grid, const LineSet& set) {
  Dataset poly;
  poly.kind = DatasetKind::polydata;
  poly.has_points = true;
  std::vector<Vec3> points, velocity;
  std::vector<double> time, speed;
  std::vector<int64_t> cell_id, seed_id, reason, n_cells;
  const auto& all = *set.lines;
  for (std::size_t l = 0; l < all.size(); ++l) {
    const Polyline& line = all[l];
    if (line.x.empty()) continue;  // a seed outside the grid has no points
    std::vector<int64_t> ids;
    for (std::size_t i = 0; i < line.x.size(); ++i) {
      ids.push_back(int64_t(points.size()));
      points.push_back(line.x[i]);
      time.push_back(line.t[i]);
      const int32_t c = line.cell[i];
      cell_id.push_back(grid.mesh().source_cell[static_cast<std::size_t>(c)]);
      const Vec3 v = velocity_at(grid, c, line.x[i]);
      speed.push_back(v.norm());
      velocity.push_back(v);
    }
    poly.lines.push_back(ids.data(), ids.size());
    seed_id.push_back(static_cast<int64_t>((*set.seed_ids)[l]));
    reason.push_back(static_cast<int>(line.reason));
    n_cells.push_back(line.cells);
  }
  poly.points = vec3_array("Points", points);
  poly.point_data.push_back(DataArray::from_doubles("IntegrationTime", 1, time));
  poly.point_data.push_back(DataArray::from_ints("CellId", 1, cell_id, vtk_type::id_type));
  poly.point_data.push_back(DataArray::from_doubles("Speed", 1, speed));
  poly.point_data.push_back(vec3_array("Velocity", velocity));
  poly.cell_data.push_back(DataArray::from_ints("SeedId", 1, seed_id, vtk_type::id_type));
  poly.cell_data.push_back(DataArray::from_ints("ReasonForTermination", 1, reason, vtk_type::int_));
  poly.cell_data.push_back(DataArray::from_ints("NumberOfCells", 1, n_cells, vtk_type::id_type));
  poly.field_data.push_back(string_array("LemtraceOptions", set.options));
  return poly;
}

Dataset tet_mesh_dataset(const TetMesh& mesh) {
  Dataset grid;
  grid.kind = DatasetKind::unstructured;
  grid.has_points = true;
  grid.points = vec3_array("Points", mesh.points);
  for (const auto& t : mesh.tets) {
    const int64_t ids[4] = {t[0], t[1], t[2], t[3]};
    grid.cells.push_back(ids, 4);
  }
  grid.cell_types.assign(mesh.tets.size(), vtk_cell::tetra);
  grid.point_data.push_back(vec3_array("velocity", mesh.vectors));
  grid.point_data.back().attribute = 1;  // active vectors
  return grid;
}

Dataset classified_dataset(const FieldGrid& grid, const std::vector<CellRecord>& records) {
  const TetMesh& mesh = grid.mesh();
  Dataset ug = tet_mesh_dataset(mesh);
  std::vector<int64_t> type, crit;
  std::vector<double> eig;
  for (std::size_t c = 0; c < mesh.tets.size(); ++c) {
    const CellRecord& r = records[c];
    type.push_back(static_cast<unsigned char>(r.type));
    const bool normal = r.type == CellType::normal_real || r.type == CellType::normal_complex;
    double e[3] = {NAN, NAN, NAN};
    if (normal) e[0] = r.lam[0], e[1] = r.lam[1], e[2] = r.lam[2];
    eig.insert(eig.end(), {e[0], e[1], e[2]});
    crit.push_back(r.critical_inside ? 1 : 0);
  }
  ug.cell_data.push_back(DataArray::from_ints("LemType", 1, type, vtk_type::unsigned_char));
  ug.cell_data.push_back(DataArray::from_doubles("Eigenvalues", 3, eig));
  ug.cell_data.push_back(DataArray::from_ints("CriticalPointInside", 1, crit, vtk_type::unsigned_char));
  return ug;
}

std::vector<Vec3> points_of(const Dataset& dataset) {
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < dataset.point_count(); ++i) {
    const auto p = dataset.point(i);
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

}  // namespace fest::lemtrace_tool

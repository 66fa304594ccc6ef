#include "core/dataset.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace fest {
namespace {

template <typename T>
double load(const unsigned char* bytes, std::size_t i) noexcept {
  T v;
  std::memcpy(&v, bytes + i * sizeof(T), sizeof(T));
  return static_cast<double>(v);
}

template <typename T>
void store_all(DataArray& a, const std::vector<double>& values) {
  a.bytes.resize(values.size() * sizeof(T));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const T v = static_cast<T>(values[i]);
    std::memcpy(a.bytes.data() + i * sizeof(T), &v, sizeof(T));
  }
}

// Number of points along each axis, or 0 where the extent is empty.
std::array<int, 3> grid_dims(const std::array<int, 6>& e) noexcept {
  std::array<int, 3> d{};
  for (int a = 0; a < 3; ++a) d[a] = std::max(0, e[2 * a + 1] - e[2 * a] + 1);
  return d;
}

}  // namespace

std::size_t vtk_type_size(int type) noexcept {
  switch (type) {
    case vtk_type::char_:
    case vtk_type::signed_char:
    case vtk_type::unsigned_char: return 1;
    case vtk_type::short_:
    case vtk_type::unsigned_short: return 2;
    case vtk_type::int_:
    case vtk_type::unsigned_int:
    case vtk_type::float_: return 4;
    case vtk_type::long_:
    case vtk_type::unsigned_long: return sizeof(long);
    case vtk_type::double_:
    case vtk_type::id_type:
    case vtk_type::long_long:
    case vtk_type::unsigned_long_long: return 8;
    default: return 0;
  }
}

double DataArray::value(std::size_t i) const noexcept {
  const unsigned char* b = bytes.data();
  switch (type) {
    case vtk_type::bit: return (b[i >> 3] & (0x80 >> (i & 7))) ? 1.0 : 0.0;
    case vtk_type::char_: return load<char>(b, i);
    case vtk_type::signed_char: return load<signed char>(b, i);
    case vtk_type::unsigned_char: return load<unsigned char>(b, i);
    case vtk_type::short_: return load<short>(b, i);
    case vtk_type::unsigned_short: return load<unsigned short>(b, i);
    case vtk_type::int_: return load<int>(b, i);
    case vtk_type::unsigned_int: return load<unsigned int>(b, i);
    case vtk_type::long_: return load<long>(b, i);
    case vtk_type::unsigned_long: return load<unsigned long>(b, i);
    case vtk_type::float_: return load<float>(b, i);
    case vtk_type::double_: return load<double>(b, i);
    case vtk_type::id_type:
    case vtk_type::long_long: return load<long long>(b, i);
    case vtk_type::unsigned_long_long: return load<unsigned long long>(b, i);
    default: return 0.0;
  }
}

const char* DataArray::type_name() const noexcept {
  // vtkImageScalarTypeNameMacro's names, as vtkAbstractArray::GetDataTypeAsString gives them.
  switch (type) {
    case vtk_type::bit: return "bit";
    case vtk_type::char_: return "char";
    case vtk_type::signed_char: return "signed char";
    case vtk_type::unsigned_char: return "unsigned char";
    case vtk_type::short_: return "short";
    case vtk_type::unsigned_short: return "unsigned short";
    case vtk_type::int_: return "int";
    case vtk_type::unsigned_int: return "unsigned int";
    case vtk_type::long_: return "long";
    case vtk_type::unsigned_long: return "unsigned long";
    case vtk_type::float_: return "float";
    case vtk_type::double_: return "double";
    case vtk_type::id_type: return "idtype";
    case vtk_type::string: return "string";
    case vtk_type::long_long: return "long long";
    case vtk_type::unsigned_long_long: return "unsigned long long";
    default: return "Undefined";
  }
}

namespace {

// An array's description without its bytes: what every from_* sets first.
DataArray described(std::string name, int components, int type, std::size_t value_count) {
  DataArray a;
  a.name = std::move(name);
  a.components = components;
  a.type = type;
  a.value_count = value_count;
  return a;
}

}  // namespace

DataArray DataArray::from_doubles(std::string name, int components, const std::vector<double>& values, int type) {
  DataArray a = described(std::move(name), components, type, values.size());
  switch (type) {
    case vtk_type::float_: store_all<float>(a, values); break;
    case vtk_type::double_: store_all<double>(a, values); break;
    case vtk_type::char_: store_all<char>(a, values); break;
    case vtk_type::signed_char: store_all<signed char>(a, values); break;
    case vtk_type::unsigned_char: store_all<unsigned char>(a, values); break;
    case vtk_type::short_: store_all<short>(a, values); break;
    case vtk_type::unsigned_short: store_all<unsigned short>(a, values); break;
    case vtk_type::int_: store_all<int>(a, values); break;
    case vtk_type::unsigned_int: store_all<unsigned int>(a, values); break;
    case vtk_type::long_: store_all<long>(a, values); break;
    case vtk_type::unsigned_long: store_all<unsigned long>(a, values); break;
    case vtk_type::id_type:
    case vtk_type::long_long: store_all<long long>(a, values); break;
    case vtk_type::unsigned_long_long: store_all<unsigned long long>(a, values); break;
    default: a.type = vtk_type::double_; store_all<double>(a, values); break;
  }
  return a;
}

DataArray DataArray::from_floats(std::string name, int components, const std::vector<float>& values) {
  DataArray a = described(std::move(name), components, vtk_type::float_, values.size());
  a.bytes.resize(values.size() * sizeof(float));
  if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  return a;
}

DataArray DataArray::from_ints(std::string name, int components, const std::vector<int64_t>& values, int type) {
  DataArray a = described(std::move(name), components, type, values.size());
  const std::size_t size = vtk_type_size(type);
  a.bytes.resize(values.size() * size);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // Little-endian machines only keep the low bytes; fest builds for those (x86-64, arm64).
    const int64_t v = values[i];
    std::memcpy(a.bytes.data() + i * size, &v, size);
  }
  return a;
}

void CellArray::push_back(const int64_t* ids, std::size_t count) {
  if (offsets.empty()) offsets.push_back(0);
  connectivity.insert(connectivity.end(), ids, ids + count);
  offsets.push_back(static_cast<int64_t>(connectivity.size()));
}

const char* Dataset::class_name() const noexcept {
  switch (kind) {
    case DatasetKind::image: return structured_points ? "vtkStructuredPoints" : "vtkImageData";
    case DatasetKind::rectilinear: return "vtkRectilinearGrid";
    case DatasetKind::structured: return "vtkStructuredGrid";
    case DatasetKind::unstructured: return "vtkUnstructuredGrid";
    case DatasetKind::polydata: return "vtkPolyData";
  }
  return "vtkDataSet";
}

std::array<int, 3> Dataset::dimensions() const noexcept { return grid_dims(extent); }

std::size_t Dataset::point_count() const noexcept {
  switch (kind) {
    case DatasetKind::image:
    case DatasetKind::rectilinear: {
      const auto d = dimensions();
      return std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(d[2]);
    }
    default: return has_points ? points.tuples() : 0;
  }
}

std::size_t Dataset::cell_count() const noexcept {
  switch (kind) {
    case DatasetKind::unstructured: return cell_types.size();
    case DatasetKind::polydata: return verts.size() + lines.size() + polys.size() + strips.size();
    default: {
      // vtkStructuredData::GetNumberOfCells: one cell per unit step along each axis
      // with more than one point; a single point is one vertex.
      const auto d = dimensions();
      if (d[0] == 0 || d[1] == 0 || d[2] == 0) return 0;
      std::size_t n = 1;
      for (int a = 0; a < 3; ++a) n *= std::size_t(d[a] > 1 ? d[a] - 1 : 1);
      return n;
    }
  }
}

std::array<double, 3> Dataset::point(std::size_t i) const noexcept {
  const auto d = dimensions();
  if (kind == DatasetKind::image || kind == DatasetKind::rectilinear) {
    const std::size_t nx = std::size_t(d[0]), nxy = nx * std::size_t(d[1]);
    const std::size_t loc[3] = {i % nx, (i / nx) % std::size_t(d[1]), i / nxy};
    if (kind == DatasetKind::rectilinear)
      return {x_coordinates.value(loc[0]), y_coordinates.value(loc[1]), z_coordinates.value(loc[2])};
    // vtkImageData::TransformIndexToPhysicalPoint: origin + direction * (spacing * index)
    double ijk[3];
    for (int a = 0; a < 3; ++a) ijk[a] = double(extent[2 * a]) + double(loc[a]);  // extents may be negative
    std::array<double, 3> x{};
    for (int r = 0; r < 3; ++r)
      x[r] = direction[3 * r] * spacing[0] * ijk[0] + direction[3 * r + 1] * spacing[1] * ijk[1] +
             direction[3 * r + 2] * spacing[2] * ijk[2] + origin[r];
    return x;
  }
  return {points.value(3 * i), points.value(3 * i + 1), points.value(3 * i + 2)};
}

namespace {

// The cell list and index within it of polydata cell i.
const CellArray* poly_cell(const Dataset& d, std::size_t& i, int& which) noexcept {
  const CellArray* lists[4] = {&d.verts, &d.lines, &d.polys, &d.strips};
  for (which = 0; which < 4; ++which) {
    if (i < lists[which]->size()) return lists[which];
    i -= lists[which]->size();
  }
  return nullptr;
}

}  // namespace

uint8_t Dataset::cell_type(std::size_t i) const noexcept {
  switch (kind) {
    case DatasetKind::unstructured: return cell_types[i];
    case DatasetKind::polydata: {
      int which = 0;
      const CellArray* list = poly_cell(*this, i, which);
      if (!list) return vtk_cell::empty;
      const int64_t n = list->offsets[i + 1] - list->offsets[i];
      switch (which) {
        case 0: return n > 1 ? vtk_cell::poly_vertex : vtk_cell::vertex;
        case 1: return n > 2 ? vtk_cell::poly_line : vtk_cell::line;
        case 2: return n == 3 ? vtk_cell::triangle : n == 4 ? vtk_cell::quad : vtk_cell::polygon;
        default: return vtk_cell::triangle_strip;
      }
    }
    default: {
      const auto d = dimensions();
      if (d[0] == 0 || d[1] == 0 || d[2] == 0) return vtk_cell::empty;
      const int axes = (d[0] > 1) + (d[1] > 1) + (d[2] > 1);
      const bool image_like = kind != DatasetKind::structured;
      switch (axes) {
        case 0: return vtk_cell::vertex;
        case 1: return vtk_cell::line;
        case 2: return image_like ? vtk_cell::pixel : vtk_cell::quad;
        default: return image_like ? vtk_cell::voxel : vtk_cell::hexahedron;
      }
    }
  }
}

void Dataset::cell_points(std::size_t i, std::vector<int64_t>& ids) const {
  ids.clear();
  const CellArray* list = nullptr;
  if (kind == DatasetKind::unstructured) {
    list = &cells;
  } else if (kind == DatasetKind::polydata) {
    int which = 0;
    list = poly_cell(*this, i, which);
  } else {
    // vtkStructuredData::GetCellPoints: the cell's corner points, i fastest.
    const auto d = dimensions();
    if (d[0] == 0 || d[1] == 0 || d[2] == 0) return;
    std::size_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, rest = i;
    for (int a = 0; a < 3; ++a) {
      if (d[a] <= 1) continue;
      const std::size_t n = std::size_t(d[a] - 1);
      lo[a] = rest % n;
      hi[a] = lo[a] + 1;
      rest /= n;
    }
    const int64_t nx = d[0], nxy = int64_t(d[0]) * d[1];
    for (std::size_t k = lo[2]; k <= hi[2]; ++k)
      for (std::size_t j = lo[1]; j <= hi[1]; ++j)
        for (std::size_t c = lo[0]; c <= hi[0]; ++c) ids.push_back(int64_t(c) + int64_t(j) * nx + int64_t(k) * nxy);
    // vtkStructuredGrid hands out quads and hexahedra, whose corners go round each
    // face, where pixels and voxels list them i fastest.
    if (kind == DatasetKind::structured && ids.size() >= 4) {
      for (std::size_t base = 0; base < ids.size(); base += 4) std::swap(ids[base + 2], ids[base + 3]);
    }
    return;
  }
  if (!list || i >= list->size()) return;
  ids.assign(list->connectivity.begin() + list->offsets[i], list->connectivity.begin() + list->offsets[i + 1]);
}

std::array<double, 6> Dataset::bounds() const noexcept {
  constexpr double big = std::numeric_limits<double>::max();
  std::array<double, 6> b{big, -big, big, -big, big, -big};
  auto include = [&b](const std::array<double, 3>& p) {
    for (int a = 0; a < 3; ++a) {
      if (std::isnan(p[a])) continue;
      b[2 * a] = std::min(b[2 * a], p[a]);
      b[2 * a + 1] = std::max(b[2 * a + 1], p[a]);
    }
  };
  const auto d = dimensions();
  if (kind == DatasetKind::image) {
    // The eight corners of the extent; for an axis-aligned image this is VTK's
    // origin + spacing * extent.
    for (int corner = 0; corner < 8; ++corner) {
      double ijk[3];
      for (int a = 0; a < 3; ++a) ijk[a] = extent[2 * a + ((corner >> a) & 1)];
      std::array<double, 3> x{};
      for (int r = 0; r < 3; ++r)
        x[r] = direction[3 * r] * spacing[0] * ijk[0] + direction[3 * r + 1] * spacing[1] * ijk[1] +
               direction[3 * r + 2] * spacing[2] * ijk[2] + origin[r];
      include(x);
    }
  } else if (kind == DatasetKind::rectilinear) {
    const DataArray* axes[3] = {&x_coordinates, &y_coordinates, &z_coordinates};
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < std::size_t(d[a]) && i < axes[a]->value_count; ++i) {
        const double v = axes[a]->value(i);
        b[2 * a] = std::min(b[2 * a], v);
        b[2 * a + 1] = std::max(b[2 * a + 1], v);
      }
  } else {
    // Every point, used by a cell or not, as VTK 9.1's vtkPointSet::ComputeBounds
    // (polygonal data included: checked against VTK in unit_dataset).
    for (std::size_t i = 0; i < point_count(); ++i) include(point(i));
  }
  return b;
}

Dataset Dataset::image_data(std::array<int, 3> dims, std::array<double, 3> spacing, std::array<double, 3> origin) {
  Dataset d;
  d.kind = DatasetKind::image;
  d.extent = {0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1};
  d.spacing = spacing;
  d.origin = origin;
  return d;
}

const DataArray* find_array(const std::vector<DataArray>& arrays, const std::string& name) noexcept {
  for (const DataArray& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace fest

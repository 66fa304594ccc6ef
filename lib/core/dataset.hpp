#pragma once
// A VTK-style dataset held without VTK: what .vtu/.vti/.vtp/.vts and legacy .vtk files
// hold (grid geometry, points, cells, point/cell/field arrays), in fest's own types, so
// that tools handle datasets without mapping VTK's libraries; only formats/dataset's
// plugin turns bytes into a Dataset and back.
//
// Cell type codes, the cell order (polygonal data: verts, lines, polys, strips) and the
// scalar type tags are VTK's (vtkCellType.h, vtkType.h), so that what is read is written
// back as it was.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fest {

// VTK's scalar type codes (vtkType.h) for the types a dataset array can hold.
namespace vtk_type {
constexpr int bit = 1, char_ = 2, unsigned_char = 3, short_ = 4, unsigned_short = 5, int_ = 6, unsigned_int = 7,
              long_ = 8, unsigned_long = 9, float_ = 10, double_ = 11, id_type = 12, string = 13,
              signed_char = 15, long_long = 16, unsigned_long_long = 17;
}  // namespace vtk_type

// VTK's cell type codes used by name in fest's code (vtkCellType.h).
namespace vtk_cell {
constexpr uint8_t empty = 0, vertex = 1, poly_vertex = 2, line = 3, poly_line = 4, triangle = 5,
                  triangle_strip = 6, polygon = 7, pixel = 8, quad = 9, tetra = 10, voxel = 11, hexahedron = 12,
                  wedge = 13, pyramid = 14;
}  // namespace vtk_cell

// One named array of tuples. Numeric values are kept as the bytes of their original
// type (native byte order; VTK_BIT packed eight to a byte, first value in the high bit),
// so int64 ids and doubles survive exactly; string arrays keep their strings.
struct DataArray {
  std::string name;  // empty: the array has no name
  int components = 1;
  int type = vtk_type::double_;  // vtk_type code
  // The attribute this array is active for in its point/cell data (VTK's attribute
  // index: 0 scalars, 1 vectors, 2 normals, 3 texture coordinates, 4 tensors, 5 global
  // ids, 6 pedigree ids, ...), -1 when none.
  int attribute = -1;
  std::vector<std::string> component_names;  // empty, or one per component
  std::vector<unsigned char> bytes;          // numeric values
  std::vector<std::string> strings;          // type == vtk_type::string
  // A legacy file's own LOOKUP_TABLE for these scalars: 4 bytes (RGBA) per entry;
  // empty for "LOOKUP_TABLE default".
  std::vector<unsigned char> lookup_table;
  std::size_t value_count = 0;               // tuples * components

  std::size_t tuples() const noexcept { return components > 0 ? value_count / std::size_t(components) : 0; }
  bool numeric() const noexcept { return type != vtk_type::string; }
  // Value i (tuple-major) as a double; 0 for string arrays.
  double value(std::size_t i) const noexcept;
  double component(std::size_t tuple, int c) const noexcept { return value(tuple * std::size_t(components) + std::size_t(c)); }
  // "float", "unsigned char", "idtype", ...: VTK's name for the type.
  const char* type_name() const noexcept;

  // New arrays of a given type from values; the values are converted to the type.
  static DataArray from_doubles(std::string name, int components, const std::vector<double>& values,
                                int type = vtk_type::double_);
  static DataArray from_floats(std::string name, int components, const std::vector<float>& values);
  static DataArray from_ints(std::string name, int components, const std::vector<int64_t>& values, int type);
};

// Size in bytes of one value of a vtk_type code; 0 for bit and string arrays and for
// codes a dataset array cannot have.
std::size_t vtk_type_size(int type) noexcept;

// A list of cells as VTK keeps it: offsets (cells + 1 entries, the first 0) into one
// connectivity list of point ids.
struct CellArray {
  std::vector<int64_t> offsets;
  std::vector<int64_t> connectivity;
  bool ids_64bit = true;  // VTK's storage width, which legacy writers show

  std::size_t size() const noexcept { return offsets.empty() ? 0 : offsets.size() - 1; }
  void push_back(const int64_t* ids, std::size_t count);
};

enum class DatasetKind { image, rectilinear, structured, unstructured, polydata };

struct Dataset {
  DatasetKind kind = DatasetKind::unstructured;

  // image, rectilinear and structured grids: index extent (VTK's i0 i1 j0 j1 k0 k1).
  std::array<int, 6> extent{0, -1, 0, -1, 0, -1};
  // image only
  bool structured_points = false;  // read as vtkStructuredPoints (legacy STRUCTURED_POINTS)
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major
  // rectilinear only: the coordinates along each axis
  DataArray x_coordinates, y_coordinates, z_coordinates;

  // structured, unstructured and polydata: 3 components per point.
  bool has_points = false;
  DataArray points;

  // unstructured: one type per cell
  std::vector<uint8_t> cell_types;
  CellArray cells;
  // polydata, in VTK's cell order
  CellArray verts, lines, polys, strips;

  std::vector<DataArray> point_data, cell_data, field_data;

  // "vtkImageData", "vtkUnstructuredGrid", ...: the VTK class the dataset is read as.
  const char* class_name() const noexcept;
  std::array<int, 3> dimensions() const noexcept;  // from the extent (grid kinds)
  std::size_t point_count() const noexcept;
  std::size_t cell_count() const noexcept;
  std::array<double, 3> point(std::size_t i) const noexcept;
  // VTK's cell type and point ids of cell i, as vtkDataSet::GetCellType/GetCellPoints.
  uint8_t cell_type(std::size_t i) const noexcept;
  void cell_points(std::size_t i, std::vector<int64_t>& ids) const;
  // As vtkDataSet::GetBounds: {xmin, xmax, ymin, ymax, zmin, zmax}; only meaningful
  // when there are points.
  std::array<double, 6> bounds() const noexcept;

  // Image data of the given size with the given spacing and origin, no arrays.
  static Dataset image_data(std::array<int, 3> dims, std::array<double, 3> spacing, std::array<double, 3> origin);
};

// The array with this name, or nullptr.
const DataArray* find_array(const std::vector<DataArray>& arrays, const std::string& name) noexcept;

}  // namespace fest

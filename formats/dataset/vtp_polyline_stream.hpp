#pragma once
// VTK XML PolyData of polylines (.vtp) written while the lines arrive, without holding
// them: the bytes are those of VTK's vtkXMLPolyDataWriter in appended raw mode with
// UInt64 block headers and no compression (what formats/dataset writes through VTK), so
// a streamed file and one written from a whole fest::Dataset are the same file.
//
// VTK's appended layout puts the header (counts, each array's RangeMin/RangeMax and
// offset) before the data, and each array's values in one block. Counts and ranges are
// known only at the end, so each per-point array goes, as the lines come, to its own
// unlinked temporary file (O_TMPFILE in `temp_dir`); finish() writes the header, now
// complete, then copies the blocks after it in VTK's order. The connectivity of
// polylines numbered in order is 0..N-1 and is generated, not stored; per-line values
// (a few per line) stay in memory. Memory: a buffer per array.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/file_io.hpp"

namespace fest::formats {

enum class VtpType { float64, int64, int32 };

struct VtpArray {
  std::string name;
  VtpType type = VtpType::float64;
  int components = 1;
  bool id_type = false;  // vtkIdTypeArray: written with IdType="1"
};

struct VtpPolylineLayout {
  std::vector<VtpArray> point_data;  // in the order of the <PointData> element
  std::vector<VtpArray> cell_data;   // one value per line, in the order of <CellData>
  std::string field_name;            // one string in <FieldData>; none when empty
  std::string field_text;
};

class VtpPolylineStream {
 public:
  // Throws Status::io when the temporaries cannot be made in `temp_dir`.
  VtpPolylineStream(VtpPolylineLayout layout, const std::string& temp_dir);
  ~VtpPolylineStream();
  VtpPolylineStream(const VtpPolylineStream&) = delete;
  VtpPolylineStream& operator=(const VtpPolylineStream&) = delete;

  // One polyline of n >= 1 points: `points` holds 3n doubles, point_data[k] the n *
  // components values of array k as little-endian bytes of its type, cell_values[k]
  // the line's value of cell array k (converted to the array's type).
  void add_line(std::size_t n, const double* points, const void* const* point_data, const double* cell_values);

  // Writes the whole file to `out`. Throws Status::io.
  void finish(OutputFile& out);

  std::uint64_t points() const noexcept { return points_; }
  std::uint64_t lines() const noexcept { return line_ends_.size(); }

  // What VTK writes as a range attribute: "%.11g", VTK_DOUBLE_MAX/-MAX for an empty array.
  static std::string range_text(double v);

 private:
  struct Spill;
  struct Range {
    double min = 1.0e+299, max = -1.0e+299;  // VTK_DOUBLE_MAX: an empty array's range
    void add(double v) {
      if (v < min) min = v;
      if (v > max) max = v;
    }
  };
  void add_values(std::size_t array, const void* data, std::size_t n);

  VtpPolylineLayout layout_;
  std::vector<std::unique_ptr<Spill>> spills_;  // point_data..., then the points
  std::vector<Range> ranges_;                   // point_data..., cell_data..., points
  std::vector<std::vector<unsigned char>> cell_bytes_;
  std::vector<std::int64_t> line_ends_;
  std::uint64_t points_ = 0;
};

}  // namespace fest::formats

#include "formats/dataset/vtp_polyline_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"
#include "core/little_endian.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "vtp_polyline_stream copies values as they lie in memory: a little-endian machine is assumed"
#endif

namespace fest::formats {

namespace {

std::size_t type_size(VtpType t) { return t == VtpType::int32 ? 4 : 8; }
const char* type_name(VtpType t) {
  switch (t) {
    case VtpType::float64: return "Float64";
    case VtpType::int64: return "Int64";
    case VtpType::int32: return "Int32";
  }
  return "";
}

double value_at(VtpType t, const unsigned char* p) {
  switch (t) {
    case VtpType::float64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    case VtpType::int64: {
      std::int64_t v;
      std::memcpy(&v, p, 8);
      return static_cast<double>(v);
    }
    case VtpType::int32: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return static_cast<double>(v);
    }
  }
  return 0;
}

std::string io_text() { return std::strerror(errno); }

// vtkXMLWriter reserves 20 characters for an attribute it fills in after writing the
// data (counts, ranges, offsets) and pads what it writes there with spaces.
void reserved(std::string& out, const char* name, const std::string& value) {
  out += ' ';
  out += name;
  out += "=\"";
  out += value;
  out += '"';
  if (value.size() < 20) out.append(20 - value.size(), ' ');
}

}  // namespace

// One array's bytes as the lines come: buffered, written to an unlinked temporary.
struct VtpPolylineStream::Spill {
  int fd = -1;
  std::vector<char> buffer;
  std::size_t used = 0;
  std::uint64_t bytes = 0;

  explicit Spill(const std::string& dir) : buffer(std::size_t(1) << 20) {
    fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (fd < 0) {  // a file system without O_TMPFILE: a named temporary, unlinked at once
      std::string name = dir + "/.fest-vtp-XXXXXX";
      fd = ::mkstemp(name.data());
      if (fd < 0) throw io_error("cannot make a temporary file: {} ({})", io_text(), dir);
      ::unlink(name.c_str());
    }
  }
  ~Spill() {
    if (fd >= 0) ::close(fd);
  }
  void flush() {
    const char* p = buffer.data();
    std::size_t left = used;
    while (left > 0) {
      const ssize_t n = ::write(fd, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw io_error("cannot write a temporary file: {}", io_text());
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    used = 0;
  }
  void append(const void* data, std::size_t n) {
    bytes += n;
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
      const std::size_t take = std::min(n, buffer.size() - used);
      std::memcpy(buffer.data() + used, p, take);
      used += take;
      p += take;
      n -= take;
      if (used == buffer.size()) flush();
    }
  }
  // The block: its UInt64 byte count, then the bytes read back from the temporary.
  void copy_to(OutputFile& out) {
    flush();
    std::string head;
    little_endian::put_u64(head, bytes);
    out.write(head);
    out.copy_from(fd, 0, bytes);
  }
};

VtpPolylineStream::VtpPolylineStream(VtpPolylineLayout layout, const std::string& temp_dir)
    : layout_(std::move(layout)) {
  for (std::size_t k = 0; k <= layout_.point_data.size(); ++k) spills_.push_back(std::make_unique<Spill>(temp_dir));
  ranges_.resize(layout_.point_data.size() + layout_.cell_data.size() + 1);
  cell_bytes_.resize(layout_.cell_data.size());
}

VtpPolylineStream::~VtpPolylineStream() = default;

std::string VtpPolylineStream::range_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.11g", v);
  return buf;
}

// VTK's ranges: the values of a one-component array; for more components the Euclidean
// norm, found as the range of the squared norms (summed in component order), then sqrt.
void VtpPolylineStream::add_values(std::size_t array, const void* data, std::size_t n) {
  const bool is_points = array == layout_.point_data.size();
  const VtpType type = is_points ? VtpType::float64 : layout_.point_data[array].type;
  const int comps = is_points ? 3 : layout_.point_data[array].components;
  const std::size_t size = type_size(type);
  const auto* p = static_cast<const unsigned char*>(data);
  Range& r = ranges_[is_points ? ranges_.size() - 1 : array];
  if (comps == 1) {
    for (std::size_t i = 0; i < n; ++i) r.add(value_at(type, p + i * size));
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      double s = 0;
      for (int c = 0; c < comps; ++c) {
        const double v = value_at(type, p + (i * std::size_t(comps) + std::size_t(c)) * size);
        s += v * v;
      }
      r.add(s);
    }
  }
  spills_[array]->append(data, n * std::size_t(comps) * size);
}

void VtpPolylineStream::add_line(std::size_t n, const double* points, const void* const* point_data,
                                 const double* cell_values) {
  if (n == 0) return;
  for (std::size_t k = 0; k < layout_.point_data.size(); ++k) add_values(k, point_data[k], n);
  add_values(layout_.point_data.size(), points, n);
  for (std::size_t k = 0; k < layout_.cell_data.size(); ++k) {
    const VtpType type = layout_.cell_data[k].type;
    unsigned char bytes[8];
    double as_double;
    if (type == VtpType::float64) {
      std::memcpy(bytes, &cell_values[k], 8);
      as_double = cell_values[k];
    } else if (type == VtpType::int64) {
      const auto v = static_cast<std::int64_t>(cell_values[k]);
      std::memcpy(bytes, &v, 8);
      as_double = static_cast<double>(v);
    } else {
      const auto v = static_cast<std::int32_t>(cell_values[k]);
      std::memcpy(bytes, &v, 4);
      as_double = static_cast<double>(v);
    }
    cell_bytes_[k].insert(cell_bytes_[k].end(), bytes, bytes + type_size(type));
    ranges_[layout_.point_data.size() + k].add(as_double);
  }
  points_ += n;
  line_ends_.push_back(static_cast<std::int64_t>(points_));
}

void VtpPolylineStream::finish(OutputFile& out) {
  const std::size_t np = layout_.point_data.size(), nc = layout_.cell_data.size();
  auto range_pair = [&](std::size_t r, int comps) {
    Range g = ranges_[r];
    if (comps > 1 && g.min <= g.max) g.min = std::sqrt(g.min), g.max = std::sqrt(g.max);
    return std::make_pair(range_text(g.min), range_text(g.max));
  };
  // Block sizes in VTK's order: field string, point data, cell data, points, then the
  // connectivity and offsets of verts, lines, strips and polys.
  std::vector<std::uint64_t> block;
  if (!layout_.field_name.empty()) block.push_back(layout_.field_text.size() + 1);
  for (std::size_t k = 0; k < np; ++k) block.push_back(spills_[k]->bytes);
  for (std::size_t k = 0; k < nc; ++k) block.push_back(cell_bytes_[k].size());
  block.push_back(spills_[np]->bytes);
  const std::uint64_t n_lines = line_ends_.size();
  for (std::uint64_t b : {std::uint64_t(0), std::uint64_t(0), points_ * 8, n_lines * 8, std::uint64_t(0),
                          std::uint64_t(0), std::uint64_t(0), std::uint64_t(0)})
    block.push_back(b);
  std::vector<std::uint64_t> offset(block.size());
  std::uint64_t at = 0;
  for (std::size_t i = 0; i < block.size(); ++i) {
    offset[i] = at;
    at += 8 + block[i];
  }

  std::string h = "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  h += "  <PolyData>\n";
  std::size_t b = 0;
  if (!layout_.field_name.empty()) {
    h += "    <FieldData>\n      <Array type=\"String\" Name=\"" + layout_.field_name +
         "\" NumberOfTuples=\"1\" format=\"appended\"";
    reserved(h, "offset", std::to_string(offset[b++]));
    h += "/>\n    </FieldData>\n";
  }
  h += "    <Piece";
  reserved(h, "NumberOfPoints", std::to_string(points_));
  reserved(h, "NumberOfVerts", "0");
  reserved(h, "NumberOfLines", std::to_string(n_lines));
  reserved(h, "NumberOfStrips", "0");
  reserved(h, "NumberOfPolys", "0");
  h += ">\n";
  auto data_array = [&](const VtpArray& a, std::size_t range_index) {
    h += "        <DataArray type=\"";
    h += type_name(a.type);
    h += '"';
    if (a.id_type) h += " IdType=\"1\"";
    h += " Name=\"" + a.name + '"';
    if (a.components != 1) h += " NumberOfComponents=\"" + std::to_string(a.components) + '"';
    h += " format=\"appended\"";
    const auto [lo, hi] = range_pair(range_index, a.components);
    reserved(h, "RangeMin", lo);
    reserved(h, "RangeMax", hi);
    reserved(h, "offset", std::to_string(offset[b++]));
    h += "/>\n";
  };
  h += "      <PointData>\n";
  for (std::size_t k = 0; k < np; ++k) data_array(layout_.point_data[k], k);
  h += "      </PointData>\n      <CellData>\n";
  for (std::size_t k = 0; k < nc; ++k) data_array(layout_.cell_data[k], np + k);
  h += "      </CellData>\n      <Points>\n";
  data_array(VtpArray{"Points", VtpType::float64, 3, false}, ranges_.size() - 1);
  h += "      </Points>\n";
  for (const char* cells : {"Verts", "Lines", "Strips", "Polys"}) {
    h += std::string("      <") + cells + ">\n";
    for (const char* name : {"connectivity", "offsets"}) {
      h += std::string("        <DataArray type=\"Int64\" Name=\"") + name + "\" format=\"appended\"";
      reserved(h, "RangeMin", "");
      reserved(h, "RangeMax", "");
      reserved(h, "offset", std::to_string(offset[b++]));
      h += "/>\n";
    }
    h += std::string("      </") + cells + ">\n";
  }
  h += "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

  // The blocks. Small ones are appended to the header's text; the per-point arrays are
  // copied from their temporaries.
  auto small_block = [&](const void* data, std::size_t n) {
    little_endian::put_u64(h, n);
    if (n > 0) h.append(static_cast<const char*>(data), n);
  };
  if (!layout_.field_name.empty()) small_block(layout_.field_text.c_str(), layout_.field_text.size() + 1);
  out.write(h);
  for (std::size_t k = 0; k < np; ++k) spills_[k]->copy_to(out);
  h.clear();
  for (std::size_t k = 0; k < nc; ++k) small_block(cell_bytes_[k].data(), cell_bytes_[k].size());
  out.write(h);
  spills_[np]->copy_to(out);
  h.clear();
  small_block(nullptr, 0);  // verts
  small_block(nullptr, 0);
  // Lines: connectivity 0..N-1 (points are numbered in line order), then the line ends.
  little_endian::put_u64(h, points_ * 8);
  std::vector<std::int64_t> ids;
  for (std::uint64_t first = 0; first < points_;) {
    const std::uint64_t count = std::min<std::uint64_t>(points_ - first, std::uint64_t(1) << 19);
    ids.resize(count);
    for (std::uint64_t i = 0; i < count; ++i) ids[i] = static_cast<std::int64_t>(first + i);
    h.append(reinterpret_cast<const char*>(ids.data()), count * 8);
    out.write(h);
    h.clear();
    first += count;
  }
  small_block(line_ends_.data(), line_ends_.size() * 8);
  for (int i = 0; i < 4; ++i) small_block(nullptr, 0);  // strips, polys
  h += "\n  </AppendedData>\n</VTKFile>\n";
  out.write(h);
}

}  // namespace fest::formats

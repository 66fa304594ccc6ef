// NumPy .npy: magic "\x93NUMPY", version, a little-endian header length, a Python dict
// literal {'descr': '<i2', 'fortran_order': False, 'shape': (H, W), } padded with spaces,
// then the raw array.

#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "formats/dem/dem_io.hpp"

namespace fest::formats {
namespace {

std::string dict_value(const std::string& header, const std::string& key) {
  const auto k = header.find("'" + key + "'");
  if (k == std::string::npos) throw bad_input(".npy header has no '{}'", key);
  auto colon = header.find(':', k);
  if (colon == std::string::npos) throw bad_input(".npy header: '{}' has no value", key);
  ++colon;
  while (colon < header.size() && header[colon] == ' ') ++colon;
  if (colon >= header.size()) throw bad_input(".npy header: '{}' has no value", key);
  const char open = header[colon];
  std::size_t end;
  if (open == '(') end = header.find(')', colon) + 1;
  else if (open == '\'') end = header.find('\'', colon + 1) + 1;
  else end = header.find_first_of(",}", colon);
  if (end == std::string::npos || end == 0 || end <= colon) throw bad_input(".npy header: bad value of '{}'", key);
  return header.substr(colon, end - colon);
}

template <typename T>
double load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return static_cast<double>(v);
}

}  // namespace

DemRaster read_npy(std::string_view bytes) {
  if (bytes.size() < 10 || bytes.substr(0, 6) != std::string_view("\x93NUMPY", 6)) throw bad_input("not a .npy file");
  const auto major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_len = 0, start = 0;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) | (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
    start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw bad_input(".npy header is truncated");
    for (int k = 3; k >= 0; --k) header_len = (header_len << 8) | static_cast<unsigned char>(bytes[8 + k]);
    start = 12;
  } else {
    throw bad_input(".npy version {} is not supported", major);
  }
  if (bytes.size() < start + header_len) throw bad_input(".npy header is truncated");
  const std::string header(bytes.substr(start, header_len));
  const std::string descr = dict_value(header, "descr");
  if (dict_value(header, "fortran_order") != "False") throw bad_input(".npy array is in Fortran order; C order needed");
  const std::string shape = dict_value(header, "shape");
  long long dims[3] = {0, 0, 0};
  int ndim = 0;
  for (std::size_t p = 1; p < shape.size() && ndim < 3;) {
    while (p < shape.size() && (shape[p] == ' ' || shape[p] == ',')) ++p;
    if (p >= shape.size() || shape[p] == ')') break;
    std::size_t used = 0;
    try {
      dims[ndim++] = std::stoll(shape.substr(p), &used);
    } catch (const std::exception&) {
      throw bad_input(".npy header: bad shape {}", shape);
    }
    p += used;
  }
  if (ndim != 2) throw bad_input(".npy array has shape {}; a 2-D array (rows, columns) is needed", shape);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[0] > (1 << 20) || dims[1] > (1 << 20))
    throw bad_input(".npy array has shape {}", shape);

  const std::string type = descr.size() >= 4 ? descr.substr(1, descr.size() - 2) : "";
  if (type.size() < 3 || type[0] == '>') throw bad_input(".npy dtype {} is not supported (little-endian ints or floats)", descr);
  const char kind = type[1];
  const int size = type[2] - '0';
  const bool ok = (kind == 'i' || kind == 'u') ? (size == 1 || size == 2 || size == 4) : kind == 'f' && (size == 4 || size == 8);
  if (!ok || type.size() != 3) throw bad_input(".npy dtype {} is not supported (little-endian ints or floats)", descr);

  DemRaster r;
  r.format = "npy";
  r.height = static_cast<int>(dims[0]);
  r.width = static_cast<int>(dims[1]);
  r.integer = kind != 'f';
  const std::size_t n = static_cast<std::size_t>(r.width) * r.height;
  const std::size_t data = start + header_len;
  if (bytes.size() - data < n * size)
    throw bad_input(".npy data is truncated: {} of {} bytes", bytes.size() - data, n * size);
  r.values.resize(n);
  const char* p = bytes.data() + data;
  for (std::size_t k = 0; k < n; ++k, p += size) {
    double v = 0;
    if (kind == 'f') v = size == 4 ? load<float>(p) : load<double>(p);
    else if (kind == 'i') v = size == 1 ? load<std::int8_t>(p) : size == 2 ? load<std::int16_t>(p) : load<std::int32_t>(p);
    else v = size == 1 ? load<std::uint8_t>(p) : size == 2 ? load<std::uint16_t>(p) : load<std::uint32_t>(p);
    r.values[k] = v;
  }
  return r;
}

}  // namespace fest::formats

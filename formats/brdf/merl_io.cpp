#include "formats/brdf/merl_io.hpp"

#include <cstdint>
#include <cstring>

#include "core/error.hpp"

namespace fest::formats {

namespace {

static_assert(sizeof(double) == 8, "MERL stores IEEE doubles");

std::int32_t get_i32(const unsigned char* p) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                                   static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24);
}

}  // namespace

MerlFile read_merl(std::string_view bytes) {
  if (bytes.size() < 12) throw bad_input("MERL file shorter than its 12-byte header (offset 0)");
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  MerlFile f;
  for (int k = 0; k < 3; ++k) f.dims[static_cast<std::size_t>(k)] = get_i32(b + 4 * k);
  if (f.dims != std::array<int, 3>{90, 90, 180})
    throw bad_input("MERL dimensions {}x{}x{}, expected 90x90x180 (offset 0)", f.dims[0], f.dims[1], f.dims[2]);
  const std::size_t n = 3u * 90u * 90u * 180u;
  if (bytes.size() != 12 + 8 * n)
    throw bad_input("MERL file has {} bytes of values at offset 12, expected {}", bytes.size() - 12, 8 * n);
  f.values.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= static_cast<std::uint64_t>(b[12 + 8 * i + static_cast<std::size_t>(k)]) << (8 * k);
    std::memcpy(&f.values[i], &v, 8);
  }
  return f;
}

std::string write_merl(const MerlFile& f) {
  std::string out;
  out.reserve(12 + 8 * f.values.size());
  for (int d : f.dims)
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((static_cast<std::uint32_t>(d) >> (8 * k)) & 0xff));
  for (double x : f.values) {
    std::uint64_t v;
    std::memcpy(&v, &x, 8);
    for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  }
  return out;
}

}  // namespace fest::formats

// NumPy .npz model reader. A .npz is a zip archive of .npy members; the zip part is
// minizip's (zlib's contrib, the Debian package libminizip-dev), the .npy part is ours
// (a 10-line header format).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>

#include <unzip.h>

#include "core/error.hpp"
#include "core/face_model_basis.hpp"
#include "core/quote.hpp"
#include "formats/facemodel/import.hpp"

namespace fest::formats {

namespace {

struct NpyArray {
  std::vector<std::uint64_t> shape;
  std::vector<double> values;  // in C (row-major) order
};

std::uint64_t product(const std::vector<std::uint64_t>& s) {
  std::uint64_t p = 1;
  for (auto v : s) p *= v;
  return p;
}

// Parses one .npy member: magic, version, header dict, data.
NpyArray parse_npy(const std::string& b, const std::string& name) {
  if (b.size() < 10 || std::memcmp(b.data(), "\x93NUMPY", 6) != 0) throw bad_input("npz member '{}' is not a .npy array", name);
  const int major = static_cast<unsigned char>(b[6]);
  std::size_t hlen, start;
  if (major == 1) {
    hlen = static_cast<unsigned char>(b[8]) | (static_cast<std::size_t>(static_cast<unsigned char>(b[9])) << 8);
    start = 10;
  } else if (major == 2 || major == 3) {
    if (b.size() < 12) throw bad_input("npz member '{}': truncated header", name);
    std::uint32_t h;
    std::memcpy(&h, b.data() + 8, 4);
    hlen = h;
    start = 12;
  } else {
    throw bad_input("npz member '{}': .npy version {} unknown", name, major);
  }
  if (hlen > b.size() - start) throw bad_input("npz member '{}': truncated header", name);
  const std::string header = b.substr(start, hlen);
  auto value_of = [&](const char* key) {
    const auto k = header.find(key);
    if (k == std::string::npos) throw bad_input("npz member '{}': header lacks {}", name, key);
    return header.substr(header.find(':', k) + 1);
  };
  std::string descr = value_of("'descr'");
  descr = descr.substr(descr.find('\'') + 1);
  descr = descr.substr(0, descr.find('\''));
  const bool fortran = value_of("'fortran_order'").find("True") < value_of("'fortran_order'").find(',');
  std::string shape_text = value_of("'shape'");
  shape_text = shape_text.substr(shape_text.find('(') + 1);
  shape_text = shape_text.substr(0, shape_text.find(')'));
  NpyArray a;
  for (std::size_t pos = 0; pos < shape_text.size();) {
    while (pos < shape_text.size() && (shape_text[pos] == ' ' || shape_text[pos] == ',')) ++pos;
    if (pos >= shape_text.size()) break;
    std::size_t end = pos;
    while (end < shape_text.size() && std::isdigit(static_cast<unsigned char>(shape_text[end]))) ++end;
    if (end == pos) throw bad_input("npz member '{}': bad shape '({})'", name, shape_text);
    a.shape.push_back(std::stoull(shape_text.substr(pos, end - pos)));
    pos = end;
  }
  std::size_t es;
  if (descr == "<f8" || descr == "<i8" || descr == "<u8") es = 8;
  else if (descr == "<f4" || descr == "<i4" || descr == "<u4") es = 4;
  else throw bad_input("npz member '{}': dtype '{}' not supported (<f4, <f8, <i4, <i8, <u4, <u8)", name, descr);
  const std::uint64_t count = product(a.shape);
  const std::size_t data = start + hlen;
  if (count > (b.size() - data) / es) throw bad_input("npz member '{}': data truncated", name);
  std::vector<double> raw(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const char* p = b.data() + data + i * es;
    if (descr == "<f8") { double v; std::memcpy(&v, p, 8); raw[i] = v; }
    else if (descr == "<f4") { float v; std::memcpy(&v, p, 4); raw[i] = v; }
    else if (descr == "<i8") { std::int64_t v; std::memcpy(&v, p, 8); raw[i] = static_cast<double>(v); }
    else if (descr == "<u8") { std::uint64_t v; std::memcpy(&v, p, 8); raw[i] = static_cast<double>(v); }
    else if (descr == "<i4") { std::int32_t v; std::memcpy(&v, p, 4); raw[i] = v; }
    else { std::uint32_t v; std::memcpy(&v, p, 4); raw[i] = v; }
  }
  if (!fortran || a.shape.size() < 2) {
    a.values = std::move(raw);
    return a;
  }
  // Fortran order to C order.
  a.values.resize(count);
  const std::size_t nd = a.shape.size();
  std::vector<std::uint64_t> idx(nd, 0);
  for (std::uint64_t f = 0; f < count; ++f) {
    std::uint64_t c = 0;
    for (std::size_t d = 0; d < nd; ++d) c = c * a.shape[d] + idx[d];
    a.values[c] = raw[f];
    for (std::size_t d = 0; d < nd; ++d) {
      if (++idx[d] < a.shape[d]) break;
      idx[d] = 0;
    }
  }
  return a;
}

std::map<std::string, NpyArray> read_members(const std::string& path) {
  unzFile z = unzOpen64(path.c_str());
  if (!z) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw io_error("cannot open '{}': {}", path, std::strerror(errno));
    std::fclose(f);
    throw bad_input("not a zip archive (.npz) ({})", path);
  }
  std::error_code size_error;
  const std::uint64_t archive_bytes = std::filesystem::file_size(path, size_error);
  if (size_error) {
    unzClose(z);
    throw io_error("cannot read the size of '{}': {}", path, size_error.message());
  }
  std::map<std::string, NpyArray> out;
  try {
    for (int rc = unzGoToFirstFile(z); rc == UNZ_OK; rc = unzGoToNextFile(z)) {
      unz_file_info64 info;
      char name[512];
      if (unzGetCurrentFileInfo64(z, &info, name, sizeof name, nullptr, 0, nullptr, 0) != UNZ_OK)
        throw bad_input("npz: unreadable zip directory ({})", path);
      if (info.uncompressed_size > (std::uint64_t{1} << 34)) throw bad_input("npz member '{}' too large ({})", name, path);
      // A directory entry sizes the allocation below, so it must be possible: the member's
      // compressed bytes lie inside the archive, and deflate expands at most 1032:1
      // (258-byte matches from 2-bit codes; stored members are their compressed size).
      // fuzz_npz_model: a 1,244-byte archive claimed a stored member of 1.7 GB.
      if (info.compressed_size > archive_bytes)
        throw bad_input("npz member '{}' claims {} compressed bytes in an archive of {} ({})", fest::quoted_bytes(name),
                        info.compressed_size, archive_bytes, path);
      if (info.uncompressed_size > info.compressed_size * 1032 + 1024)
        throw bad_input("npz member '{}' claims {} bytes from {} compressed, more than deflate can give ({})",
                        fest::quoted_bytes(name), info.uncompressed_size, info.compressed_size, path);
      std::string bytes(info.uncompressed_size, '\0');
      if (unzOpenCurrentFile(z) != UNZ_OK) throw bad_input("npz: cannot open member '{}' ({})", name, path);
      const int got = bytes.empty() ? 0 : unzReadCurrentFile(z, bytes.data(), static_cast<unsigned>(bytes.size()));
      const int closed = unzCloseCurrentFile(z);
      if (got < 0 || static_cast<std::uint64_t>(got) != info.uncompressed_size || closed != UNZ_OK)
        throw bad_input("npz: member '{}' is corrupt or truncated ({})", name, path);
      std::string key = name;
      if (key.size() > 4 && key.compare(key.size() - 4, 4, ".npy") == 0) key.resize(key.size() - 4);
      out[key] = parse_npy(bytes, key);
    }
  } catch (...) {
    unzClose(z);
    throw;
  }
  unzClose(z);
  return out;
}

const NpyArray* find(const std::map<std::string, NpyArray>& m, std::initializer_list<const char*> names, std::string* found = nullptr) {
  for (const char* n : names)
    if (auto it = m.find(n); it != m.end()) {
      if (found) *found = n;
      return &it->second;
    }
  return nullptr;
}

}  // namespace

face::Model read_npz_model(const std::string& path, std::string* warnings) {
  const auto members = read_members(path);
  const NpyArray* mean = find(members, {"mean", "shapeMU", "shape_mean"});
  const NpyArray* basis = find(members, {"basis", "shapePC", "pcaBasis"});
  std::string sigma_key;
  const NpyArray* sigma = find(members, {"sigma", "shapeEV"}, &sigma_key);
  const NpyArray* variance = find(members, {"variance", "pcaVariance", "eigenvalues"});
  if (!mean || !basis || (!sigma && !variance))
    throw bad_input("npz needs arrays mean|shapeMU|shape_mean, basis|shapePC|pcaBasis and sigma|shapeEV or "
                    "variance|pcaVariance|eigenvalues ({})",
                    path);
  const std::uint64_t n = mean->values.size();
  if (n == 0 || n % 3 != 0) throw bad_input("npz: mean has {} values, not a multiple of 3 ({})", n, path);
  // The basis: rows = product of all but the last axis (so FLAME's p×3×k works), unless
  // stored transposed (k×n).
  const std::uint64_t total = basis->values.size();
  if (basis->shape.empty() || total % n != 0) throw bad_input("npz: basis size {} does not match the mean's {} values ({})", total, n, path);
  const std::uint64_t k = total / n;
  const bool transposed = basis->shape.size() == 2 && basis->shape[0] == k && basis->shape[1] == n && k != n;
  Eigen::MatrixXd B(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
  for (std::uint64_t r = 0; r < n; ++r)
    for (std::uint64_t c = 0; c < k; ++c)
      B(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = transposed ? basis->values[c * n + r] : basis->values[r * k + c];
  face::Model m;
  m.dims = 3;
  m.points = n / 3;
  m.components = k;
  m.mean = mean->values;
  const NpyArray* s = sigma ? sigma : variance;
  if (s->values.size() < k) throw bad_input("npz: {} standard deviations for {} components ({})", s->values.size(), k, path);
  m.sigma.assign(s->values.begin(), s->values.begin() + static_cast<std::ptrdiff_t>(k));
  if (!sigma)
    for (auto& v : m.sigma) v = std::sqrt(v);
  if (const NpyArray* t = find(members, {"triangles", "tl", "cells"})) {
    const auto& v = t->values;
    if (v.size() % 3 != 0) throw bad_input("npz: triangle array of {} values ({})", v.size(), path);
    const std::size_t count = v.size() / 3;
    const bool three_by_t = t->shape.size() == 2 && t->shape[0] == 3 && t->shape[1] != 3;
    double lo = 1e300;
    for (double x : v) lo = std::min(lo, x);
    const double base = lo == 1 ? 1 : 0;
    if (base == 1 && warnings) *warnings += "triangle indices are 1-based: subtracted 1; ";
    for (std::size_t i = 0; i < count; ++i) {
      std::array<std::uint32_t, 3> tri{};
      for (int e = 0; e < 3; ++e) {
        const double x = (three_by_t ? v[static_cast<std::size_t>(e) * count + i] : v[3 * i + static_cast<std::size_t>(e)]) - base;
        if (!(x >= 0 && x < static_cast<double>(m.points))) throw bad_input("npz: triangle vertex {} out of range ({})", x, path);
        tri[static_cast<std::size_t>(e)] = static_cast<std::uint32_t>(x);
      }
      m.triangles.push_back(tri);
    }
  }
  face::set_owned_basis_f32(m, B);
  m.source = "npz model (" + path + ")";
  return m;
}

}  // namespace fest::formats

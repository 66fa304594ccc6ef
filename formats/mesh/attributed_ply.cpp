#include "formats/mesh/attributed_ply.hpp"

#include <cstring>

#include "core/error.hpp"

namespace fest::formats {
namespace {

std::size_t type_size(const std::string& t) {
  if (t == "float" || t == "int") return 4;
  if (t == "double") return 8;
  if (t == "uchar") return 1;
  throw bad_input("PLY writer: unknown property type '{}'", t);
}

template <typename T>
void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));  // little-endian hosts only (the project builds on amd64/arm64)
  out.append(b, sizeof(T));
}

void put_value(std::string& out, const std::string& type, double v) {
  if (type == "float") put(out, static_cast<float>(v));
  else if (type == "double") put(out, v);
  else if (type == "int") put(out, static_cast<std::int32_t>(v));
  else put(out, static_cast<std::uint8_t>(v));
}

std::size_t column_length(const std::vector<PlyColumn>& cols, const char* element) {
  if (cols.empty()) return 0;
  const std::size_t n = cols.front().values.size();
  for (const PlyColumn& c : cols) {
    type_size(c.type);
    if (c.values.size() != n)
      throw bad_input("PLY writer: {} property {} has {} values, {} expected", element, c.name, c.values.size(), n);
  }
  return n;
}

}  // namespace

std::string write_attributed_ply(const AttributedPly& ply) {
  const std::size_t nv = column_length(ply.vertex, "vertex");
  const std::size_t nf = ply.faces.size();
  if (!ply.face.empty() && column_length(ply.face, "face") != nf)
    throw bad_input("PLY writer: face properties do not match the {} faces", nf);
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& c : ply.comments) {
    if (c.find_first_of("\r\n") != std::string::npos) throw bad_input("PLY writer: a comment holds a line break");
    out += "comment " + c + "\n";
  }
  out += "element vertex " + std::to_string(nv) + "\n";
  for (const PlyColumn& c : ply.vertex) out += "property " + c.type + " " + c.name + "\n";
  out += "element face " + std::to_string(nf) + "\n";
  out += "property list uchar int vertex_indices\n";
  for (const PlyColumn& c : ply.face) out += "property " + c.type + " " + c.name + "\n";
  out += "end_header\n";
  for (std::size_t v = 0; v < nv; ++v)
    for (const PlyColumn& c : ply.vertex) put_value(out, c.type, c.values[v]);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& face = ply.faces[f];
    if (face.size() < 3 || face.size() > 255) throw bad_input("PLY writer: face {} has {} corners", f, face.size());
    put(out, static_cast<std::uint8_t>(face.size()));
    for (std::uint32_t i : face) {
      if (i >= nv) throw bad_input("PLY writer: face {} names vertex {} of {}", f, i, nv);
      put(out, static_cast<std::int32_t>(i));
    }
    for (const PlyColumn& c : ply.face) put_value(out, c.type, c.values[f]);
  }
  return out;
}

}  // namespace fest::formats

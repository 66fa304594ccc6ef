#include "formats/mesh/attributed_ply.hpp"
#include "core/quote.hpp"

#include <cmath>
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

// --- reading -------------------------------------------------------------------------

#include "formats/mesh/ply_body.hpp"
#include "formats/mesh/ply_header.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats {
namespace {

// Every element of the body into `out` (vertex and face scalars as columns, the face
// index lists as faces); returns the vertex count the header declares.
template <class Source>
std::uint64_t read_elements(Source& src, const mesh_detail::PlyHeader& header, AttributedPly& out) {
  std::uint64_t nv = 0;
  for (const auto& e : header.elements) {
    if (e.name == "vertex") nv = e.count;
    const bool vertex = e.name == "vertex", face = e.name == "face";
    std::vector<PlyColumn>* cols = vertex ? &out.vertex : face ? &out.face : nullptr;
    std::vector<int> column_of(e.properties.size(), -1);
    int indices = -1;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const auto& p = e.properties[k];
      if (face && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!mesh_detail::ply_type_is_integer(p.type)) throw bad_input("PLY header: face {} must hold integers", fest::quoted_bytes(p.name));
        indices = static_cast<int>(k);
        continue;
      }
      if (!cols) continue;
      if (p.is_list) throw bad_input("PLY: {} list property {} is not supported", fest::quoted_bytes(e.name), fest::quoted_bytes(p.name));
      column_of[k] = static_cast<int>(cols->size());
      cols->push_back({p.name, mesh_detail::ply_type_name(p.type), {}});
      cols->back().values.reserve(static_cast<std::size_t>(e.count));
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const auto& p = e.properties[k];
        double v;
        if (p.is_list) {
          // The count is checked as a double first: a float-typed count of 1e120 must not
          // reach the integer conversion (undefined; fuzz_radiosity_scene). No list of 2^32
          // entries can fit the body anyway.
          if (!src.read(p.count_type, v) || !(v >= 0 && v < 4294967296.0) || v != std::floor(v) ||
              !src.can_hold(static_cast<std::uint64_t>(v), p.type))
            throw bad_input("PLY body: {} {} has a bad {} list", fest::quoted_bytes(e.name), i + 1, fest::quoted_bytes(p.name));
          const auto n = static_cast<std::uint64_t>(v);
          std::vector<std::uint32_t> list;
          for (std::uint64_t j = 0; j < n; ++j) {
            if (!src.read(p.type, v)) throw bad_input("PLY body: {} {} is truncated", fest::quoted_bytes(e.name), i + 1);
            if (static_cast<int>(k) == indices) {
              if (!(v >= 0 && v <= 4294967295.0)) throw bad_input("PLY body: face {} has index {}", i + 1, v);
              list.push_back(static_cast<std::uint32_t>(v));
            }
          }
          if (static_cast<int>(k) == indices) out.faces.push_back(std::move(list));
          continue;
        }
        if (!src.read(p.type, v)) throw bad_input("PLY body: {} {} of {} is truncated or not a number", fest::quoted_bytes(e.name), i + 1, e.count);
        if (column_of[k] >= 0) (*cols)[static_cast<std::size_t>(column_of[k])].values.push_back(v);
      }
    }
    if (face && indices < 0 && e.count > 0) throw bad_input("PLY header: face element has no vertex_indices list");
  }
  if (std::size_t extra = src.trailing(); extra != 0)
    throw bad_input("PLY: {} bytes of unexpected data after the last element", extra);
  return nv;
}

}  // namespace

AttributedPly read_attributed_ply(std::string_view bytes) {
  const mesh_detail::PlyHeader header = mesh_detail::parse_ply_header(bytes);
  AttributedPly out;
  // Comments: the header lines that start with "comment ".
  {
    mesh_detail::TextCursor c(bytes.substr(0, header.body_offset));
    std::string_view line;
    while (c.next_line(line))
      if (line.substr(0, 8) == "comment ") out.comments.emplace_back(line.substr(8));
  }
  const std::uint64_t nv =
      mesh_detail::with_ply_source(bytes, header, [&](auto& src) { return read_elements(src, header, out); });
  for (const auto& f : out.faces)
    for (std::uint32_t idx : f)
      if (idx >= nv) throw bad_input("PLY: a face names vertex {} of {}", idx, nv);
  return out;
}

}  // namespace fest::formats
